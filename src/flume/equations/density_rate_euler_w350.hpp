// Density rate of SPH for the Euler equations, W (3.50):
//   d rho_i/dt = -(1/2) (rho_i^2 / p_i) sum_j m_j (p_j/rho_j^2 + p_i/rho_i^2) u_ji . grad_i psi_ij,
// u_ji = u_j - u_i, derived from the energy equation W (3.52) so that the entropy condition
// holds. It divides by p_i: for a liquid (Tait, p = 0 at the free surface) p is replaced by 1,
// the form it takes for a uniform pressure (methods.md erratum 6):
//   d rho_i/dt = -(1/2) rho_i^2 sum_j m_j (1/rho_j^2 + 1/rho_i^2) u_ji . grad_i psi_ij.
// With q = p (gas) or 1 (liquid), the pair term (q_i/rho_i^2 + q_j/rho_j^2) u_ji . grad_i psi_ij
// is the same seen from j (u_ij . grad_j psi_ji, both factors change sign): i gets m_j times it,
// j gets m_i times it. `vel` is the velocity of the rates (leapfrog.hpp, runge_kutta.hpp).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"
#include "flume/equations/smoothing_length_w222.hpp"

namespace flume {

template <int D>
struct DensityRateEulerW350 {
  using Acc = double;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;                          // q_b / rho_b^2
  ParticleSet<D>& ps;
  const std::vector<Vec<D>>& vel;
  bool gas;  // q = p (gas) or 1 (liquid)

  double q(std::size_t b) const { return gas ? ps.p[b] : 1.0; }
  Acc init(std::size_t) const { return 0.0; }
  Own own(std::size_t b) const { return q(b) / (ps.rho[b] * ps.rho[b]); }
  void pair(Acc& s_i, Acc& s_j, Own o_i, Own o_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const double s = (o_i + o_j) * dot(vel[j] - vel[i], g.gradw);
    s_i += ps.m[j] * s;
    s_j += ps.m[i] * s;
  }
  void finish(Acc& s, std::size_t i) const {
    ps.drho[i] = -0.5 * ps.rho[i] * ps.rho[i] / q(i) * s;
    smoothing_length_rate_w222(ps, i);
  }
};

}  // namespace flume
