// Internal energy rate of weak SPH, W (3.81), and of R-SPH, W (4.21) (correct as printed):
//   d e_i/dt = -sum_j m_j / (rho_i rho_j) (p_j + Pi_ij / 2) (u_j - u_i) . G_ij,
// the partner of the force W (3.80) / (4.20): sum m (e + u^2/2) is conserved (W 3.3.2).
// (u_j - u_i) . G_ij and 1/(rho_i rho_j) are the same seen from j, so i gets
// m_j (p_j + Pi/2) times their product and j gets m_i (p_i + Pi/2) times it.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/force_weak_w380.hpp"
#include "flume/equations/kernel_gradient_w416.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D, class Gradient = PlainGradient>
struct EnergyWeakW381 {
  using Acc = double;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;                          // 1 / rho_b
  ParticleSet<D>& ps;
  const std::vector<Vec<D>>& vel;
  double alpha;
  double beta;

  Acc init(std::size_t) const { return 0.0; }
  Own own(std::size_t b) const { return 1.0 / ps.rho[b]; }
  void pair(Acc& s_i, Acc& s_j, Own inv_rho_i, Own inv_rho_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const double half_pi = 0.5 * artificial_pressure_w318(ps, vel, alpha, beta, i, j, g);
    const double s = dot(vel[j] - vel[i], Gradient::of(ps, i, j, g)) * (inv_rho_i * inv_rho_j);
    s_i += ps.m[j] * (ps.p[j] + half_pi) * s;
    s_j += ps.m[i] * (ps.p[i] + half_pi) * s;
  }
  void finish(Acc& s, std::size_t i) const { ps.de[i] = -s; }
};

}  // namespace flume
