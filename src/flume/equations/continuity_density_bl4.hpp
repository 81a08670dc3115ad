// Continuity density, BL (2) with the divergence BL (4) (= W (3.21)):
//   d rho_a/dt = -rho_a sum_b V_b (v_b - v_a) . grad W_b(x_a),   V_b = m_b / rho_b.
// Variationally consistent with the force BL (20). `vel` is the velocity field used: the
// leap-frog evaluates the rate with v^{n+1/2} (leapfrog.hpp). For the pair (a, b) = (i, j),
// (v_j - v_i) . grad_i W_ij is the same seen from either side (both factors change sign), so
// a gets V_j times it and b gets V_i times it.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct ContinuityDensityBL4 {
  using Acc = double;  // sum_b V_b (v_b - v_a) . grad W_b(x_a), the divergence of v at a
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;  // the volume V_b = m_b / rho_b, computed once per particle (own.hpp)
  ParticleSet<D>& ps;
  const std::vector<Vec<D>>& vel;

  Acc init(std::size_t) const { return 0.0; }
  Own own(std::size_t b) const { return ps.m[b] / ps.rho[b]; }
  void pair(Acc& div_i, Acc& div_j, Own vol_i, Own vol_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const double dv_gradw = dot(vel[j] - vel[i], g.gradw);
    div_i += vol_j * dv_gradw;
    div_j += vol_i * dv_gradw;
  }
  void finish(Acc& div, std::size_t i) const { ps.drho[i] = -ps.rho[i] * div; }
};

}  // namespace flume
