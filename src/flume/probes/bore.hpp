// Front position and height of a bore running away from the wall at x = wall_x (BL 5.4, Fig 12),
// from the particles of the main body of water (fluid_body.hpp: spray thrown off a breaking
// front does not count). 2D: x along the flow, y vertical.
//
// 1. The depth: eta(x) = sum_i m_i B(x - x_i) / rho0, sampled every dx from the wall (dx/2,
//    3 dx/2, ...), with B the cubic B-spline of knot spacing dx normalised to unit integral
//    (BL's cubic kernel in 1D with h = dx), mirrored at the wall. It is the depth of water at
//    the reference density, the depth of the theory (BL (67)-(68) balance the mass and momentum
//    of incompressible water); it does not depend on how the particles near the surface are
//    arranged, and an overturning jet or a roller counts for the water it holds, not for the
//    height it reaches. The B-spline's shifts sum to one, so a lattice layer reads its depth
//    exactly wherever it stands (bins would alias a moving lattice by a whole column).
//    (Masses per unit depth, as every 2D mass in flume.)
// 2. Where the bore is: X1, the right-most sample whose eta is more than 2 dx above h0. Ahead of
//    the bore the layer is undisturbed (it moves as a block with the push wall), so its depth
//    stays within a spacing of h0 and X1 lies at the bore's front.
// 3. Its height: the median eta of the samples between X1/4 and 3 X1/4, away from the run-up at
//    the wall and from the front's toe; the median also steps over an undular bore's ripples.
// 4. Its front: where eta falls through the mid-level (h0 + height)/2 for the last time going
//    away from the wall, interpolated linearly between samples.
// Before the bore has risen 2 dx above h0 the front is 0 and the height is eta at the wall.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/probes/water_depth.hpp"

namespace flume {

struct BoreMeasure {
  double front = 0.0;   // m from the wall
  double height = 0.0;  // m of water
};

inline BoreMeasure measure_bore(const ParticleSet<2>& ps, const std::vector<char>& in_body,
                                double wall_x, double rho0, double h0, double spacing) {
  std::vector<double> eta;  // at (c + 1/2) dx from the wall
  const auto add = [&](long c, double w) {
    if (c < 0) c = -1 - c;  // the mirror image's share
    const auto k = static_cast<std::size_t>(c);
    if (k >= eta.size()) eta.resize(k + 1, 0.0);
    eta[k] += w;
  };
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    if (!in_body[i]) continue;
    const double s = (ps.x[i][0] - wall_x) / spacing - 0.5;  // in samples
    if (!(s >= -0.5)) continue;
    const double amount = ps.m[i] / (rho0 * spacing);
    const auto base = static_cast<long>(std::floor(s));
    for (long c = base - 1; c <= base + 2; ++c) {
      const double b = cubic_bspline(s - static_cast<double>(c));
      if (b > 0.0) add(c, amount * b);
    }
  }
  const auto centre = [&](std::size_t c) { return (static_cast<double>(c) + 0.5) * spacing; };
  BoreMeasure out;
  if (eta.empty()) return out;
  out.height = eta.front();

  std::size_t last_high = eta.size();  // X1's sample
  for (std::size_t c = eta.size(); c-- > 0;)
    if (eta[c] > h0 + 2.0 * spacing) {
      last_high = c;
      break;
    }
  if (last_high == eta.size()) return out;
  const double x1 = centre(last_high);

  std::vector<double> middle;
  for (std::size_t c = 0; c <= last_high; ++c)
    if (centre(c) >= 0.25 * x1 && centre(c) <= 0.75 * x1) middle.push_back(eta[c]);
  if (middle.empty()) middle.push_back(eta[last_high]);
  std::sort(middle.begin(), middle.end());
  const std::size_t m = middle.size();
  out.height = m % 2 ? middle[m / 2] : 0.5 * (middle[m / 2 - 1] + middle[m / 2]);

  const double level = 0.5 * (h0 + out.height);
  out.front = x1;
  for (std::size_t c = 0; c + 1 < eta.size(); ++c) {
    if (eta[c] >= level && eta[c + 1] < level) {
      const double w = (eta[c] - level) / (eta[c] - eta[c + 1]);
      out.front = centre(c) + w * spacing;
    }
  }
  // Without a crossing (not possible while the layer ahead reads h0) the front is X1.
  return out;
}

}  // namespace flume
