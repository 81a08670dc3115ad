// Semi-axes of a 2D drop that stays an axis-aligned ellipse (BL 5.2), from the particles'
// mass-weighted second moments about their centre (theory/elliptical_drop.hpp):
//   a(t) = a0 sqrt(<(x - xc)^2>_t / <(x - xc)^2>_0),   likewise b(t) along y,
// with a0, b0 the drop's nominal semi-axes (its fluid block's). The moments are those of a
// uniform ellipse, <x^2> = a^2 / 4, but a particle cloud's differ from that at t = 0 (a random
// cloud of 1184 points by ~1.5 %, a lattice by its staircase rim): taken relative to the start,
// the ratio is exact for any cloud moved by a linear velocity field (the moments transform as
// F <x x^T> F^T), which is the exact solution's motion, so the probe measures the flow, not the
// cloud's sampling.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/theory/elliptical_drop.hpp"

namespace flume {

class SemiAxesProbe {
 public:
  explicit SemiAxesProbe(std::array<double, 2> nominal) : nominal_(nominal) {}

  // {a, b} now; the first call sets the reference moments (call it at t = 0).
  std::array<double, 2> operator()(const ParticleSet<2>& ps) {
    std::vector<double> x(ps.n_real), y(ps.n_real), m(ps.n_real);
    for (std::size_t i = 0; i < ps.n_real; ++i) {
      x[i] = ps.x[i][0];
      y[i] = ps.x[i][1];
      m[i] = ps.m[i];
    }
    const auto now = semi_axes_from_moments(x, y, m);
    if (!start_) start_ = now;
    return {nominal_[0] * now[0] / (*start_)[0], nominal_[1] * now[1] / (*start_)[1]};
  }

 private:
  // The reference moments (a checkpoint's probe_state): empty before the first call.
 public:
  std::vector<double> state() const {
    return start_ ? std::vector<double>{(*start_)[0], (*start_)[1]} : std::vector<double>{};
  }
  void restore(const std::vector<double>& s) {
    if (s.size() == 2) start_ = std::array<double, 2>{s[0], s[1]};
  }

 private:
  std::array<double, 2> nominal_;
  std::optional<std::array<double, 2>> start_;
};

}  // namespace flume
