// Velocity gradient, BL (22):  grad v_a = sum_b V_b (v_b - v_a) (x) grad W_b(x_a),  V_b =
// m_b/rho_b. The -v_a term makes the gradient of a uniform field vanish. Feeds the viscous stress
// BL (24).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct VelocityGradientBL22 {
  using Acc = Mat<D>;
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  void pair(Acc& G, std::size_t i, const Pair<D>& g) const {
    const double vol = ps.m[g.j] / ps.rho[g.j];
    G += outer(ps.v[g.j] - ps.v[i], g.gradw) * vol;
  }
  void finish(Acc& G, std::size_t i) const { ps.grad_v[i] = G; }
};

}  // namespace flume
