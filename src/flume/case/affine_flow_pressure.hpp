// The pressure of an ellipsoidal body of incompressible fluid in the straining flow
// v = G (x - c), G = diag(g_k) with sum_k g_k = 0 (fluid_blocks initial_pressure =
// "velocity_field"): the exact solution that BL 5.2's drop is compared with. The flow stays
// affine, so the acceleration is (dG/dt + G^2)(x - c), and -grad p / rho0 must equal it with
// p = 0 on the surface sum_k (x_k - c_k)^2 / r_k^2 = 1 (r_k the semi-axes). Hence
//   p(x) = (rho0 / 2) P (1 - sum_k (x_k - c_k)^2 / r_k^2),   dg_k/dt + g_k^2 = P / r_k^2,
// and incompressibility (sum_k dg_k/dt = 0) fixes
//   P = sum_k g_k^2 / sum_k r_k^-2.
// For BL's drop, G = diag(-A, A) on the ellipse (a, b): P = 2 A^2 a^2 b^2 / (a^2 + b^2) and
// dA/dt = P / b^2 - A^2 = A^2 (a^2 - b^2) / (a^2 + b^2), the ODE of theory/elliptical_drop.hpp.
// A weakly compressible run started at uniform density has no pressure: it coasts until sound
// has crossed the body (R / c0 = 0.7 ms for BL's drop) and its b rings about the exact one
// (0.15 % at t = 1 ms); started at rho(p) it follows the exact solution from the first step.
#pragma once

#include <cstddef>

#include "flume/case/case_spec.hpp"

namespace flume {

// P of the header, m^2/s^2 (a pressure per unit density): sum_k g_k^2 / sum_k r_k^-2.
inline double affine_flow_pressure_scale(const FluidBlock& block, int dimension) {
  double g2 = 0.0, inv_r2 = 0.0;
  for (int k = 0; k < dimension; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const double g = block.velocity_gradient[kk * static_cast<std::size_t>(dimension) + kk];
    const double r = 0.5 * (block.max[kk] - block.min[kk]);
    g2 += g * g;
    inv_r2 += 1.0 / (r * r);
  }
  return g2 / inv_r2;
}

// p(x), Pa, for a fluid of density rho0 (zero on the ellipsoid, negative outside it).
template <class V>
double affine_flow_pressure(const FluidBlock& block, int dimension, double rho0, const V& x) {
  double q = 0.0;
  for (int k = 0; k < dimension; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const double r = 0.5 * (block.max[kk] - block.min[kk]);
    const double d = (x[k] - 0.5 * (block.min[kk] + block.max[kk])) / r;
    q += d * d;
  }
  return 0.5 * rho0 * affine_flow_pressure_scale(block, dimension) * (1.0 - q);
}

}  // namespace flume
