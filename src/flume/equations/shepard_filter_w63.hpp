// Shepard density filter, W (6.3):  rho_i <- sum_j rho_j w_j W_ij / sum_j w_j W_ij with
// w_j = m_j / rho_j, i.e. sum_j m_j W_ij / sum_j (m_j / rho_j) W_ij (self term included).
// A zeroth-order-consistent average of the density over the kernel: it removes the particle-scale
// density noise that a continuity density accumulates (W applies it every 40 steps, W 6.2).
// The result goes to `out`, not ps.rho, so that every particle averages the old densities.
// W is symmetric: each particle of a pair gets the other's terms.
#pragma once

#include <array>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct ShepardFilterW63 {
  using Acc = std::array<double, 2>;  // sum m_j W_ij, sum (m_j / rho_j) W_ij
  using Own = double;  // the volume V_b = m_b / rho_b, computed once per particle (own.hpp)
  const ParticleSet<D>& ps;
  std::vector<double>& out;

  Acc init(std::size_t) const { return {0.0, 0.0}; }
  Own own(std::size_t b) const { return ps.m[b] / ps.rho[b]; }
  void pair(Acc& s_i, Acc& s_j, Own vol_i, Own vol_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    s_i[0] += ps.m[j] * g.w;
    s_i[1] += vol_j * g.w;
    s_j[0] += ps.m[i] * g.w;
    s_j[1] += vol_i * g.w;
  }
  void finish(Acc& s, std::size_t i) const { out[i] = s[0] / s[1]; }
};

}  // namespace flume
