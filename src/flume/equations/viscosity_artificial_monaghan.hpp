// Artificial viscosity of Monaghan, W (3.18)-(3.19):
//   Pi_ij = -alpha c_ij rho_ij mu_ij + beta rho_ij mu_ij^2  if u_ij . x_ij < 0, else 0,
//   mu_ij = h_ij u_ij . x_ij / (|x_ij|^2 + eta^2),
// with bars for pair averages. Pi_ij has units of pressure (it is rho_bar times Monaghan's usual
// Pi), so it enters the momentum equation as Pi_ij / rho_bar^2 (errata.md, W (3.18)-(3.19)):
//   a_i -= sum_j m_j Pi_ij / rho_ij^2 grad_i W_ij.
// eta^2 = 0.01 h_ij^2, the usual choice (W does not give eta).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/eos_tait.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct ViscosityArtificialMonaghan {
  using Acc = Vec<D>;
  ParticleSet<D>& ps;
  const TaitEos& eos;
  double alpha;
  double beta;

  Acc init(std::size_t) const { return {}; }
  // The cheap test stays inline; the rest is out of line, so a run without artificial viscosity
  // pays one predictable branch per pair.
  void pair(Acc& a, std::size_t i, const Pair<D>& g) const {
    if (alpha != 0.0 || beta != 0.0) add_pair(a, i, g);
  }
  [[gnu::noinline]] void add_pair(Acc& a, std::size_t i, const Pair<D>& g) const {
    const double ux = dot(ps.v[i] - ps.v[g.j], g.xij);
    if (ux >= 0.0) return;
    const double mu_ij = g.h * ux / (g.r * g.r + 0.01 * g.h * g.h);
    const double rho_bar = 0.5 * (ps.rho[i] + ps.rho[g.j]);
    // From the pressures the sweep already has (ghosts' refreshed too): two square roots per
    // pair instead of two pows.
    const double c_bar =
        0.5 * (eos.sound_speed(ps.rho[i], ps.p[i]) + eos.sound_speed(ps.rho[g.j], ps.p[g.j]));
    const double pi_ij = rho_bar * mu_ij * (-alpha * c_bar + beta * mu_ij);
    a -= g.gradw * (ps.m[g.j] * pi_ij / (rho_bar * rho_bar));
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
