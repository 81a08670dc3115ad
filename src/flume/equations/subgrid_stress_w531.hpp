// LES-SPH's sub-grid stress, W (5.31)-(5.32) (Smagorinsky with Yoshizawa's isotropic part):
//   tau_kl - (1/3) tau_mm delta_kl = -2 rho nu_r (S_kl - (1/3) S_mm delta_kl),      (5.31)
//   tau_mm = 2 C_I rho Delta^2 |S|^2,                                                (5.32)
//   nu_r = (C_s Delta)^2 |S|,  |S| = sqrt(2 S_kl S_kl),  S = (G + G^T) / 2,
// with nu_r as W (5.19) prints it (methods.md erratum 7: the text after (5.32) drops a C_s),
// Delta the filter width (W: the initial spacing), C_s = 0.12, C_I = 0.0066. The momentum
// equation, corrected to per-unit-mass form (erratum 7), is
//   d u_i/dt = -sum_j m_j/(rho_i rho_j) (p_i + p_j) grad_i psi_ij
//              + sum_j m_j/(rho_i rho_j) (sigma_i + sigma_j) . grad_i psi_ij
//              - sum_j m_j/(rho_i rho_j) (tau_i + tau_j) . grad_i psi_ij,
// so the sub-grid stress enters BL (24)'s pair form (viscosity_bonet_lok_24.hpp) as -tau:
//   -tau = 2 rho nu_r S' - (2/3) C_I rho Delta^2 |S|^2 I,   S' = S - (1/3) tr(S) I,
// an eddy viscosity rho nu_r added to mu on the deviator and a sub-grid pressure. The 2D
// deviator keeps 1/3 (plane strain), as BL (23) does.
#pragma once

#include <cmath>

#include "flume/core/vec.hpp"
#include "flume/schemes/physics.hpp"

namespace flume {

template <int D>
struct SubgridStress {
  Mat<D> minus_tau;  // -tau_i, Pa
  double nu_r;       // the eddy viscosity, m^2/s
};

template <int D>
inline SubgridStress<D> subgrid_stress_w531(const Mat<D>& grad_v, double rho,
                                            const Smagorinsky& les) {
  Mat<D> s = (grad_v + transpose(grad_v)) * 0.5;
  double ss = 0.0;
  for (int k = 0; k < D; ++k)
    for (int l = 0; l < D; ++l)
      ss += s(k, l) * s(k, l);
  const double abs_s = std::sqrt(2.0 * ss);
  const double nu_r = les.cs * les.delta * les.cs * les.delta * abs_s;
  const double third_tr = trace(s) / 3.0;
  for (int k = 0; k < D; ++k)
    s(k, k) -= third_tr;
  Mat<D> minus_tau = s * (2.0 * rho * nu_r);
  const double isotropic = (2.0 / 3.0) * les.ci * rho * les.delta * les.delta * abs_s * abs_s;
  for (int k = 0; k < D; ++k)
    minus_tau(k, k) -= isotropic;
  return {minus_tau, nu_r};
}

}  // namespace flume
