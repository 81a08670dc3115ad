// Momentum equation of weak SPH, W (3.80), and of R-SPH, W (4.20):
//   d u_i/dt = -sum_j m_j / (rho_i rho_j) (p_j + p_i + Pi_ij) G_ij,
// G_ij = grad_i psi_ij or B_ij grad_i psi_ij (kernel_gradient_w416.hpp); Pi_ij the artificial
// viscosity W (3.18) in pressure units (rho_bar^2 times viscosity_artificial_monaghan.hpp's
// Pi_ij / rho_bar^2). With G plain and Pi = 0 this is BL (20). The pair force is antisymmetric
// (G_ji = -G_ij, the rest symmetric): i gets -m_j f, j gets +m_i f, so total linear momentum
// is kept to round-off.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/kernel_gradient_w416.hpp"
#include "flume/equations/pair.hpp"
#include "flume/equations/viscosity_artificial_monaghan.hpp"

namespace flume {

// Pi_ij of W (3.18), Pa: the pair's Pi / rho_bar^2 times rho_bar^2.
template <int D>
double artificial_pressure_w318(const ParticleSet<D>& ps, const std::vector<Vec<D>>& vel,
                                double alpha, double beta, std::size_t i, std::size_t j,
                                const Pair<D>& g) {
  const double rho_bar = 0.5 * (ps.rho[i] + ps.rho[j]);
  return artificial_viscosity_w318(ps, vel, alpha, beta, i, j, g) * rho_bar * rho_bar;
}

template <int D, class Gradient = PlainGradient>
struct ForceWeakW380 {
  using Acc = Vec<D>;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;                          // 1 / rho_b
  ParticleSet<D>& ps;
  double alpha;
  double beta;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return 1.0 / ps.rho[b]; }
  void pair(Acc& a_i, Acc& a_j, Own inv_rho_i, Own inv_rho_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const double pi = artificial_pressure_w318(ps, ps.v, alpha, beta, i, j, g);
    const Vec<D> f =
        Gradient::of(ps, i, j, g) * ((ps.p[i] + ps.p[j] + pi) * (inv_rho_i * inv_rho_j));
    a_i -= f * ps.m[j];
    a_j += f * ps.m[i];
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
