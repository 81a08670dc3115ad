// Summation density, BL (1) / W (3.55):  rho_a = sum_b m_b W_b(x_a)   (self term included).
// Variationally consistent with the force BL (7). W is symmetric, so the pair gives
// m_b W to a and m_a W to b.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct DensitySummation {
  using Acc = double;
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return 0.0; }
  void pair(Acc& rho_i, Acc& rho_j, std::size_t i, std::size_t j, const Pair<D>& g) const {
    rho_i += ps.m[j] * g.w;
    rho_j += ps.m[i] * g.w;
  }
  void finish(Acc& rho, std::size_t i) const { ps.rho[i] = rho; }
};

}  // namespace flume
