// Pressure force BL (20) = W (3.80), variationally consistent with the continuity density BL (4):
//   T_a = sum_b V_a V_b (p_a + p_b) grad W_a(x_b),   V = m/rho.
// Compression positive (methods.md erratum 1): a_a = +T_a/m_a, i.e.
//   a_a = -sum_b m_b/(rho_a rho_b) (p_a + p_b) grad_a W_ab.
// Used with the summation density BL (1) it is the "+" form of BL (8): the inconsistent pair of
// BL Fig 10. The pair force is antisymmetric and central.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct ForceBonetLok20 {
  using Acc = Vec<D>;
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  void pair(Acc& a, std::size_t i, const Pair<D>& g) const {
    a -= g.gradw * (ps.m[g.j] / (ps.rho[i] * ps.rho[g.j]) * (ps.p[i] + ps.p[g.j]));
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
