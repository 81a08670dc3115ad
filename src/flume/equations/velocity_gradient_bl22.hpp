// Velocity gradient, BL (22):  grad v_a = sum_b V_b (v_b - v_a) (x) grad W_b(x_a),  V_b =
// m_b/rho_b. The -v_a term makes the gradient of a uniform field vanish. Feeds the viscous stress
// BL (24). Seen from b, both v_a - v_b and grad W_a(x_b) change sign, so the pair's outer product
// is the same for both: a gets V_b times it, b gets V_a times it.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct VelocityGradientBL22 {
  using Acc = Mat<D>;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;  // the volume V_b = m_b / rho_b, computed once per particle (own.hpp)
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return ps.m[b] / ps.rho[b]; }
  void pair(Acc& G_i, Acc& G_j, Own vol_i, Own vol_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const Mat<D> dv_gradw = outer(ps.v[j] - ps.v[i], g.gradw);
    G_i += dv_gradw * vol_j;
    G_j += dv_gradw * vol_i;
  }
  void finish(Acc& G, std::size_t i) const { ps.grad_v[i] = G; }
};

}  // namespace flume
