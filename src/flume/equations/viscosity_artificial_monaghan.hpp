// Artificial viscosity of Monaghan, W (3.18)-(3.19):
//   Pi_ij = -alpha c_ij rho_ij mu_ij + beta rho_ij mu_ij^2  if u_ij . x_ij < 0, else 0,
//   mu_ij = h_ij u_ij . x_ij / (|x_ij|^2 + eta^2),
// with bars for pair averages. Pi_ij has units of pressure (it is rho_bar times Monaghan's usual
// Pi), so it enters the momentum equation as Pi_ij / rho_bar^2 (errata.md, W (3.18)-(3.19)):
//   a_i -= sum_j m_j Pi_ij / rho_ij^2 grad_i W_ij.
// eta^2 = 0.01 h_ij^2, the usual choice (W does not give eta). Pi_ij is symmetric, so the pair
// force is antisymmetric: i gets -m_j f, j gets +m_i f. The local sound speeds c are those of
// the equation of state, computed once per particle with the pressure (ps.c).
#pragma once

#include <algorithm>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

// Pi_ij / rho_bar_ij^2 of W (3.18)-(3.19) for the pair g = (i, j), with the velocities `vel`
// (the force's v; the gas schemes' energy equations pass the velocity field of their rates).
// Written without a branch (the sweep vectorises it): min(u.x, 0) switches receding pairs off,
// and Pi_ij / rho_bar^2 = h ux (-alpha c_bar + beta mu) / ((r^2 + eta^2) rho_bar) takes one
// division.
template <int D>
[[gnu::always_inline]] inline double artificial_viscosity_w318(const ParticleSet<D>& ps,
                                                               const std::vector<Vec<D>>& vel,
                                                               double alpha, double beta,
                                                               std::size_t i, std::size_t j,
                                                               const Pair<D>& g) {
  const double ux = std::min(dot(vel[i] - vel[j], g.xij), 0.0);  // receding pairs: 0
  const double rho_bar = 0.5 * (ps.rho[i] + ps.rho[j]);
  const double c_bar = 0.5 * (ps.c[i] + ps.c[j]);
  const double inv = 1.0 / ((g.r * g.r + 0.01 * g.h * g.h) * rho_bar);
  const double mu_ij = g.h * ux * rho_bar * inv;
  return g.h * ux * inv * (-alpha * c_bar + beta * mu_ij);  // Pi_ij / rho_bar^2
}

template <int D>
struct ViscosityArtificialMonaghan {
  using Acc = Vec<D>;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  ParticleSet<D>& ps;
  double alpha;
  double beta;

  Acc init(std::size_t) const { return {}; }
  // Central: f = s grad_i W_ij with s = Pi_ij / rho_bar^2 (own.hpp, HasRadial).
  static constexpr bool kRadial = true;
  double radial(std::size_t i, std::size_t j, const Pair<D>& g) const {
    return artificial_viscosity_w318(ps, ps.v, alpha, beta, i, j, g);
  }
  void pair(Acc& a_i, Acc& a_j, std::size_t i, std::size_t j, const Pair<D>& g) const {
    const Vec<D> f = g.gradw * radial(i, j, g);
    a_i -= f * ps.m[j];
    a_j += f * ps.m[i];
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
