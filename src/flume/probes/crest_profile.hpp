// The shape of a solitary wave's crest against the KdV solitary wave W (6.15),
//   eta(x) - H = A sech^2((x - x_c) / lambda),   lambda_KdV(A) = sqrt(4 H^3 / (3 A))  W (6.17),
// read from the depth profile (water_depth.hpp) around the crest the wave probe found (its
// position x_c and amplitude A, wave_probes.hpp), over the offsets s = k dx from the crest with
// |s| <= kCrestWindow lambda_KdV(A) (dx the profile's sample spacing; eta read by the profile's
// linear interpolation, wrapped around in a periodic tank; offsets beyond a wall are left out):
// - width: the least-squares lambda of A sech^2(s / lambda) against eta - H with A and x_c as
//   measured (the data's own width: a wave that is too wide for its height reads wider than
//   lambda_KdV(A));
// - shape: the root mean square of (eta - H) - A sech^2(s / lambda_KdV(A)) over the offsets,
//   divided by A: how far the measured profile is from KdV's profile of the same height (0 for
//   a KdV wave; a sech^2 wave whose width is off by a small fraction f reads about 0.37 f);
// - fit_amplitude: the amplitude of the least-squares A' sech^2(s / lambda') with both A' and
//   lambda' free (x_c as measured). A is one sample's height, parabola-refined: where the top
//   of a wave is a few particles wide, those few particles move it; the fit weighs every sample
//   of the window, so the wave's whole crest sets it (W 6.4.2's heights after a collision,
//   against the same wave alone, differ by a few %). For a given lambda' the best A' is linear
//   least squares, A' = sum eta phi / sum phi^2 with phi = sech^2(s / lambda'), which leaves
//   sum (eta - A' phi)^2 = sum eta^2 - (sum eta phi)^2 / sum phi^2 to minimise over lambda'
//   alone (variable projection), by the same search as the width.
// The window, +-3 lambda_KdV, holds the whole wave (sech^2(3) = 0.01) and little of what trails
// it. The least squares are minimised by golden-section search on log lambda over
// [lambda_KdV / 8, 8 lambda_KdV] (a fixed number of steps: the same result for the same
// profile); the misfit of a single hump is unimodal in lambda there.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "flume/probes/water_depth.hpp"
#include "flume/theory/solitary_wave.hpp"

namespace flume {

inline constexpr double kCrestWindow = 3.0;  // KdV widths either side of the crest

struct CrestProfile {
  double width = 0.0;          // m: least-squares lambda; 0 when there is no crest (A <= 0)
  double shape = 0.0;          // RMS deviation from KdV's profile of amplitude A, over A
  double fit_amplitude = 0.0;  // m: A' of the least-squares A' sech^2(s / lambda'); 0: no crest
};

// The u in [lo, hi] that minimises f (unimodal there): golden-section search, a fixed number
// of steps (80: the bracket shrinks to 1e-16 of its length), so the same f gives the same u.
template <class F>
double golden_minimum(const F& f, double lo, double hi) {
  const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
  double u1 = hi - phi * (hi - lo), u2 = lo + phi * (hi - lo);
  double f1 = f(u1), f2 = f(u2);
  for (int it = 0; it < 80; ++it) {
    if (f1 <= f2) {
      hi = u2;
      u2 = u1;
      f2 = f1;
      u1 = hi - phi * (hi - lo);
      f1 = f(u1);
    } else {
      lo = u1;
      u1 = u2;
      f1 = f2;
      u2 = lo + phi * (hi - lo);
      f2 = f(u2);
    }
  }
  return 0.5 * (lo + hi);
}

inline CrestProfile crest_profile(const DepthProfile& d, double still_depth, double crest_x,
                                  double amplitude) {
  CrestProfile out;
  if (!(amplitude > 0.0) || d.eta.empty()) return out;
  const double kdv = kdv_width(amplitude, still_depth);
  // The offsets and the elevations there.
  std::vector<double> s, eta;
  const auto k_max = static_cast<long>(std::floor(kCrestWindow * kdv / d.dx));
  const double x_end = d.x_lo + d.length();
  for (long k = -k_max; k <= k_max; ++k) {
    const double off = static_cast<double>(k) * d.dx;
    const double x = crest_x + off;
    if (!d.periodic && (x < d.x_lo || x > x_end)) continue;
    s.push_back(off);
    eta.push_back(d.at(x) - still_depth);
  }
  if (s.empty()) return out;
  auto misfit = [&](double lambda) {
    double sum = 0.0;
    for (std::size_t k = 0; k < s.size(); ++k) {
      const double c = std::cosh(s[k] / lambda);
      const double e = eta[k] - amplitude / (c * c);
      sum += e * e;
    }
    return sum;
  };
  const double n = static_cast<double>(s.size());
  out.shape = std::sqrt(misfit(kdv) / n) / amplitude;
  // Both searches on u = log(lambda / kdv) in [-log 8, log 8].
  const double span = std::log(8.0);
  out.width = kdv * std::exp(golden_minimum([&](double u) { return misfit(kdv * std::exp(u)); },
                                            -span, span));
  // A' free: sums of eta phi and phi^2 at lambda'.
  auto projected = [&](double lambda) {
    double ep = 0.0, pp = 0.0;
    for (std::size_t k = 0; k < s.size(); ++k) {
      const double c = std::cosh(s[k] / lambda);
      const double phi = 1.0 / (c * c);
      ep += eta[k] * phi;
      pp += phi * phi;
    }
    return std::pair{ep, pp};
  };
  const double u = golden_minimum(
      [&](double v) {
        const auto [ep, pp] = projected(kdv * std::exp(v));
        return -ep * ep / pp;  // sum (eta - A' phi)^2 less the constant sum eta^2
      },
      -span, span);
  const auto [ep, pp] = projected(kdv * std::exp(u));
  out.fit_amplitude = ep / pp;
  return out;
}

}  // namespace flume
