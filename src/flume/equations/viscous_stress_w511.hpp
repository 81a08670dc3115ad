// The viscous terms of W (5.11) as a stress tensor per particle:
//   d u_i/dt += mu sum_j m_j/(rho_i rho_j) grad_h(u_i + u_j) . grad_i psi_ij
//             + (lambda + mu) sum_j m_j/(rho_i rho_j) (div_h u_i + div_h u_j) grad_i psi_ij,
// with grad_h u_i from W (5.5) and omega_j = m_j / rho_j (methods.md erratum 8: not W (5.13)),
// which is BL (22)'s velocity gradient G_i = ps.grad_v[i], (G)_{kl} = d u_k / d x_l. Both sums
// have the form sum_j m_j/(rho_i rho_j) (T_i + T_j) grad_i psi_ij of BL (24)'s pair
// (viscosity_bonet_lok_24.hpp) with
//   T_i = mu G_i + (lambda + mu) tr(G_i) I,    lambda = -2 mu / 3 (Stokes, W after (5.13)),
// the discrete form of mu lap u + (mu / 3) grad div u, where BL (24) discretises the same
// continuum operator as div(2 mu d'). The two differ in the discretisation only: W (5.4)'s
// double summation applies the SPH divergence to the SPH gradient of u.
#pragma once

#include "flume/core/vec.hpp"

namespace flume {

template <int D>
inline Mat<D> navier_stokes_stress_w511(const Mat<D>& grad_v, double mu) {
  const double lambda = -2.0 * mu / 3.0;
  Mat<D> t = grad_v * mu;
  const double bulk = (lambda + mu) * trace(grad_v);
  for (int k = 0; k < D; ++k)
    t(k, k) += bulk;
  return t;
}

}  // namespace flume
