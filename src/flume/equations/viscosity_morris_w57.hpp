// Physical viscosity through Morris's Laplacian, W (5.7):
//   lap u_i = 2 sum_j omega_j u_ij (x_ij . grad_i psi_ij) / |x_ij|^2,   omega_j = m_j / rho_j,
// an SPH first derivative of the kernel with a finite difference of u along x_ij (W App. A).
// The momentum equation takes (mu / rho_i) lap u_i; with omega_j = m_j / rho_j the pair factor
// m_j / (rho_i rho_j) is symmetric in i and j, so
//   a_i += sum_j m_j f_ij,   f_ij = 2 mu u_ij (x_ij . grad_i W_ij) / (rho_i rho_j (r^2 + eta^2)),
// and seen from j, u_ji = -u_ij while x_ji . grad_j W_ji = x_ij . grad_i W_ij: j gets -m_i f_ij.
// The pair force is antisymmetric (linear momentum kept to round-off) but along u_ij, not x_ij,
// so angular momentum is not kept. eta^2 = 0.01 h^2 keeps the pair finite at r = 0, as in the
// artificial viscosity W (3.19). For u = (y^2, 0), lap u = (2, 0) in any dimension: the lattice
// sum reproduces it (tests/properties/test_viscous_laplacians.cpp).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct ViscosityMorrisW57 {
  using Acc = Vec<D>;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;                          // 1 / rho_b
  ParticleSet<D>& ps;
  double mu;  // dynamic viscosity, Pa s

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return 1.0 / ps.rho[b]; }
  void pair(Acc& a_i, Acc& a_j, Own inv_rho_i, Own inv_rho_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const double s =
        2.0 * mu * dot(g.xij, g.gradw) * (inv_rho_i * inv_rho_j) / (g.r * g.r + 0.01 * g.h * g.h);
    const Vec<D> f = (ps.v[i] - ps.v[j]) * s;
    a_i += f * ps.m[j];
    a_j -= f * ps.m[i];
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
