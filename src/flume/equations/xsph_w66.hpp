// XSPH, W (6.6): particles move with a velocity nearer their neighbourhood's mean,
//   d x_i/dt = u_i + eps sum_j m_j / rho_bar_ij (u_j - u_i) psi_ij,   rho_bar_ij = (rho_i +
//   rho_j)/2,
// 0 <= eps <= 1 (0.5 usual; W does not use it). This sweep gives the correction term (the sum
// times eps) into ps.xsph; the integrators add it to the drift velocity. The velocity u is the
// integrator's (leap-frog's v^{n+1/2}, a Runge-Kutta stage's v). Seen from j the term is
// m_i / rho_bar (u_i - u_j) psi_ij: the same product, opposite sign, other mass. The self pair
// adds u_i - u_i = 0. Linear momentum is untouched (the velocities are not changed), and
// sum_i m_i (correction)_i = 0 to round-off: the mean drift velocity is the mean velocity.
#pragma once

#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct XsphW66 {
  using Acc = Vec<D>;
  ParticleSet<D>& ps;
  const std::vector<Vec<D>>& u;  // the velocity field the drift uses (ghosts refreshed)
  double eps;                    // XSPH's eps, -

  Acc init(std::size_t) const { return {}; }
  void pair(Acc& x_i, Acc& x_j, std::size_t i, std::size_t j, const Pair<D>& g) const {
    const Vec<D> f = (u[j] - u[i]) * (2.0 * g.w / (ps.rho[i] + ps.rho[j]));
    x_i += f * ps.m[j];
    x_j -= f * ps.m[i];
  }
  void finish(Acc& x, std::size_t i) const { ps.xsph[i] = x * eps; }
};

}  // namespace flume
