// The depth of water along a 2D tank from the particles' masses (x along the tank, y up):
//   eta(x) = sum_i m_i B((x - x_i) / dx) / (rho0 dx),
// with B the cubic B-spline of knot spacing dx normalised to unit integral, sampled at the
// centres x_lo + (c + 1/2) dx of the tank's dx-wide columns. eta is the depth the water would
// have at the reference density: the depth of the shallow-water and KdV theories, which balance
// the mass of incompressible water. It does not depend on how the particles near the surface are
// arranged (a lattice layer reads its depth exactly wherever it stands, since the B-spline's
// shifts sum to one), and an overturning crest counts for the water it holds. The bore probe
// (bore.hpp) reads its depth the same way. Smoothing by B (variance dx^2 / 3) lowers the crest of
// a solitary wave of width lambda by about dx^2 / lambda^2: 1e-3 at lambda = 30 dx.
// Ends: mirror walls fold the B-spline's share beyond a wall back into the tank (the wall's ghost
// water), a periodic tank wraps it around.
// Over a beach (a wall of repulsive particles, repulsive_walls.hpp) the masses give the water's
// thickness; given the bed's height at each sample, eta is then the surface's elevation, the
// bed's height plus the thickness where the water is at least half a spacing thick, and 0 where
// the beach is dry (no crest, a gauge reading -H). The wall holds the water off by up to its
// reach (Monaghan-Kos's, 2h unless the case sets it), so over a beach eta reads low by about that
// gap; and a thin sheet
// running up the beach reads its elevation, which can exceed a crest's once a wave runs up.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "flume/core/particle_set.hpp"

namespace flume {

// The cubic B-spline of unit knot spacing at distance q (unit integral, support |q| < 2).
inline double cubic_bspline(double q) {
  q = std::abs(q);
  return q < 1.0   ? 2.0 / 3.0 - q * q + 0.5 * q * q * q
         : q < 2.0 ? (2.0 - q) * (2.0 - q) * (2.0 - q) / 6.0
                   : 0.0;
}

// The number of dx-wide columns over [x_lo, x_hi] (at least one).
inline long column_count(double x_lo, double x_hi, double dx) {
  return std::max(1L, std::lround((x_hi - x_lo) / dx));
}

struct DepthProfile {
  double x_lo = 0.0;        // m: the tank's start; sample c stands at x_lo + (c + 1/2) dx
  double dx = 0.0;          // m
  bool periodic = false;    // the tank's ends are one (a periodic tank)
  std::vector<double> eta;  // m of water at each sample

  double centre(std::size_t c) const { return x_lo + (static_cast<double>(c) + 0.5) * dx; }
  double length() const { return static_cast<double>(eta.size()) * dx; }
  // eta at x, linear between samples (constant beyond the first and last in a walled tank,
  // wrapped around in a periodic one).
  double at(double x) const {
    const double s = (x - x_lo) / dx - 0.5;
    const auto n = static_cast<long>(eta.size());
    if (n == 0) return 0.0;
    auto c = static_cast<long>(std::floor(s));
    const double w = s - static_cast<double>(c);
    const auto sample = [&](long k) {
      if (periodic) return eta[static_cast<std::size_t>(((k % n) + n) % n)];
      return eta[static_cast<std::size_t>(k < 0 ? 0 : k >= n ? n - 1 : k)];
    };
    return (1.0 - w) * sample(c) + w * sample(c + 1);
  }
};

// The depth profile over [x_lo, x_hi] of the real particles (those with in_body[i] set, when
// given), sampled every dx (the columns: round((x_hi - x_lo) / dx); in a tank whose length is
// not a whole number of spacings the last column's edge, not the wall, is the upper mirror, a
// fraction of a spacing off).
inline DepthProfile depth_profile(const ParticleSet<2>& ps, const std::vector<char>* in_body,
                                  double x_lo, double x_hi, double rho0, double dx, bool periodic,
                                  const std::vector<double>* bed = nullptr) {
  DepthProfile out;
  out.x_lo = x_lo;
  out.dx = dx;
  out.periodic = periodic;
  const long n = column_count(x_lo, x_hi, dx);
  out.eta.assign(static_cast<std::size_t>(n), 0.0);
  const auto fold = [&](long c) {
    if (periodic) return ((c % n) + n) % n;
    if (c < 0) c = -1 - c;                   // the lower wall's mirror image
    if (c >= n) c = 2 * n - 1 - c;           // the upper wall's
    return c < 0 ? 0L : c >= n ? n - 1 : c;  // a particle more than a tank beyond (none)
  };
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    if (in_body && !(*in_body)[i]) continue;
    const double s = (ps.x[i][0] - x_lo) / dx - 0.5;  // in samples
    if (!std::isfinite(s)) continue;
    const double amount = ps.m[i] / (rho0 * dx);
    const auto base = static_cast<long>(std::floor(s));
    for (long c = base - 1; c <= base + 2; ++c) {
      const double b = cubic_bspline(s - static_cast<double>(c));
      if (b > 0.0) out.eta[static_cast<std::size_t>(fold(c))] += amount * b;
    }
  }
  if (bed && bed->size() == out.eta.size())
    for (std::size_t c = 0; c < out.eta.size(); ++c)
      if ((*bed)[c] > 0.0) out.eta[c] = out.eta[c] >= 0.5 * dx ? out.eta[c] + (*bed)[c] : 0.0;
  return out;
}

// The bed's height above the floor at the centres of the columns of depth_profile over
// [x_lo, x_hi] (spacing dx): the highest of the beaches over each (segments from (x0, y0) to
// (x1, y1), taken over their x-range), 0 where there is none.
inline std::vector<double> bed_heights(const std::vector<std::array<double, 4>>& beaches,
                                       double x_lo, double x_hi, double dx, double floor) {
  const long n = column_count(x_lo, x_hi, dx);
  std::vector<double> bed(static_cast<std::size_t>(n), 0.0);
  for (long c = 0; c < n; ++c) {
    const double x = x_lo + (static_cast<double>(c) + 0.5) * dx;
    for (const auto& [x0, y0, x1, y1] : beaches) {
      const double lo = std::min(x0, x1), hi = std::max(x0, x1);
      if (!(x >= lo && x <= hi) || hi == lo) continue;
      const double y = y0 + (y1 - y0) * (x - x0) / (x1 - x0) - floor;
      bed[static_cast<std::size_t>(c)] = std::max(bed[static_cast<std::size_t>(c)], y);
    }
  }
  return bed;
}

struct Crest {
  double x = 0.0;       // m
  double height = 0.0;  // m of water
};

namespace detail {
// Sample c of the profile, folded at walls or wrapped in a periodic tank.
inline double sample(const DepthProfile& d, long c) {
  const auto n = static_cast<long>(d.eta.size());
  if (d.periodic) return d.eta[static_cast<std::size_t>(((c % n) + n) % n)];
  return d.eta[static_cast<std::size_t>(c < 0 ? -1 - c : c >= n ? 2 * n - 1 - c : c)];
}
// The crest at sample `top`: the vertex of the parabola through it and its two neighbours
// (exact for a profile that is quadratic near the crest).
inline Crest refine(const DepthProfile& d, long top) {
  const double em = sample(d, top - 1), e0 = sample(d, top), ep = sample(d, top + 1);
  const double curvature = em - 2.0 * e0 + ep;
  double offset = curvature < 0.0 ? 0.5 * (em - ep) / curvature : 0.0;  // in samples
  offset = std::max(-0.5, std::min(0.5, offset));
  return {d.centre(static_cast<std::size_t>(top)) + offset * d.dx, e0 - 0.25 * (em - ep) * offset};
}
}  // namespace detail

// The highest point of the profile: the largest sample, refined by the parabola through it and
// its two neighbours.
inline Crest highest_crest(const DepthProfile& d) {
  const auto n = static_cast<long>(d.eta.size());
  if (n == 0) return {};
  long top = 0;
  for (long c = 1; c < n; ++c)
    if (d.eta[static_cast<std::size_t>(c)] > d.eta[static_cast<std::size_t>(top)]) top = c;
  return detail::refine(d, top);
}

// The centre of the crest c: the centroid of the profile's excess over half the crest's height
// above `base` (the still depth), eta - (base + (c.height - base) / 2), over the run of samples
// around the crest that exceed that level (the samples stand at unwrapped positions, so the
// centre may lie beyond the tank's end in a periodic one). On a symmetric hump it is the crest
// itself; where the crest is flat and noisy (a wave whose top is a few particles wide) the
// highest sample hops between them while the centroid of the upper half moves smoothly, so a
// speed read from it is steadier. c.x when there is no crest above base.
inline double crest_centre(const DepthProfile& d, const Crest& c, double base) {
  const auto n = static_cast<long>(d.eta.size());
  const double level = base + 0.5 * (c.height - base);
  if (n == 0 || !(c.height > base)) return c.x;
  const long top = std::clamp(static_cast<long>(std::floor((c.x - d.x_lo) / d.dx)), 0L, n - 1);
  double sum_w = 0.0, sum_wx = 0.0;
  auto add = [&](long k) {
    if (!d.periodic && (k < 0 || k >= n)) return false;  // a wall ends the crest
    const double w = detail::sample(d, k) - level;
    if (!(w > 0.0)) return false;
    sum_w += w;
    sum_wx += w * (d.x_lo + (static_cast<double>(k) + 0.5) * d.dx);
    return true;
  };
  // At most half the tank's length each way: a periodic tank's samples wrap around.
  if (!add(top)) return c.x;
  for (long k = top + 1; k < top + n / 2 && add(k);)
    ++k;
  for (long k = top - 1; k > top - n / 2 && add(k);)
    --k;
  return sum_wx / sum_w;
}

// The highest local maximum (a sample at least as high as both neighbours) at least `away`
// from x_avoid (the distance around the tank in a periodic one): a second wave beside the
// highest crest. NaNs when there is none.
inline Crest highest_crest_away_from(const DepthProfile& d, double x_avoid, double away) {
  const auto n = static_cast<long>(d.eta.size());
  long top = -1;
  for (long c = 0; c < n; ++c) {
    double gap = std::abs(d.centre(static_cast<std::size_t>(c)) - x_avoid);
    if (d.periodic) gap = std::min(gap, d.length() - gap);
    const double e = d.eta[static_cast<std::size_t>(c)];
    if (gap < away || e < detail::sample(d, c - 1) || e < detail::sample(d, c + 1)) continue;
    if (top < 0 || e > d.eta[static_cast<std::size_t>(top)]) top = c;
  }
  if (top < 0) return {std::nan(""), std::nan("")};
  return detail::refine(d, top);
}

}  // namespace flume
