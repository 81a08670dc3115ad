// Continuity density, BL (2) with the divergence BL (4) (= W (3.21)):
//   d rho_a/dt = -rho_a sum_b V_b (v_b - v_a) . grad W_b(x_a).
// Variationally consistent with the force BL (20). `vel` is the velocity field used: the
// leap-frog evaluates the rate with v^{n+1/2} (leapfrog.hpp).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct ContinuityDensityBL4 {
  using Acc = double;
  ParticleSet<D>& ps;
  const std::vector<Vec<D>>& vel;

  Acc init(std::size_t) const { return 0.0; }
  void pair(Acc& div, std::size_t i, const Pair<D>& g) const {
    div += ps.m[g.j] / ps.rho[g.j] * dot(vel[g.j] - vel[i], g.gradw);
  }
  void finish(Acc& div, std::size_t i) const { ps.drho[i] = -ps.rho[i] * div; }
};

}  // namespace flume
