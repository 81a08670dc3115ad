// Internal energy rate of SPH for the Euler equations, W (3.52) (correct as printed):
//   d e_i/dt = -(1/2) sum_j m_j (p_j/rho_j^2 + p_i/rho_i^2 + Pi_ij/rho_bar_ij^2) u_ji . grad_i
//   psi_ij,
// the partner of the force W (3.51) (= BL (7) + artificial viscosity W (3.18)): with it,
// sum m (e + u^2/2) is conserved, W (3.61). The pair term is the same seen from j (as in
// W (3.50)): i gets m_j times it, j gets m_i times it. Pi_ij / rho_bar^2 is that of the force
// (viscosity_artificial_monaghan.hpp), with the velocity `vel` of the rates.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"
#include "flume/equations/viscosity_artificial_monaghan.hpp"

namespace flume {

template <int D>
struct EnergyEulerW352 {
  using Acc = double;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;                          // p_b / rho_b^2
  ParticleSet<D>& ps;
  const std::vector<Vec<D>>& vel;
  double alpha;
  double beta;

  Acc init(std::size_t) const { return 0.0; }
  Own own(std::size_t b) const { return ps.p[b] / (ps.rho[b] * ps.rho[b]); }
  void pair(Acc& s_i, Acc& s_j, Own o_i, Own o_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const double pi = artificial_viscosity_w318(ps, vel, alpha, beta, i, j, g);
    const double s = (o_i + o_j + pi) * dot(vel[j] - vel[i], g.gradw);
    s_i += ps.m[j] * s;
    s_j += ps.m[i] * s;
  }
  void finish(Acc& s, std::size_t i) const { ps.de[i] = -0.5 * s; }
};

}  // namespace flume
