// Physical viscosity through the velocity gradient, BL (22)-(25), with BL (24)'s V_b V_b read as
// V_a V_b (methods.md erratum 3). In BL's tension-positive convention
//   T_a^mu = sum_b V_a V_b (sigma'_a + sigma'_b) grad W_a(x_b),  sigma' = 2 mu d'.
// flume is compression positive with total stress sigma = -p I + sigma' (erratum 1), so the
// deviatoric stress enters with the opposite sign to p:
//   a_a += sum_b m_b/(rho_a rho_b) (sigma'_a + sigma'_b) grad_a W_ab.
// The deviator is BL (23)'s d' = d - (1/3) tr(d) I also in 2D: plane strain (d_zz = 0) of a
// physical 3D fluid, so the 2D and 3D instantiations describe the same fluid. The pair force is
// antisymmetric: a gets +m_b f, b gets -m_a f with f = (sigma'_a + sigma'_b) grad_a W_ab /
// (rho_a rho_b).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

// sigma' = 2 mu d',  d = (G + G^T)/2,  d' = d - tr(d)/3 I  (BL (23)-(24)).
template <int D>
inline Mat<D> deviatoric_stress(const Mat<D>& grad_v, double mu) {
  Mat<D> d = (grad_v + transpose(grad_v)) * 0.5;
  const double third_tr = trace(d) / 3.0;
  for (int k = 0; k < D; ++k)
    d(k, k) -= third_tr;
  return d * (2.0 * mu);
}

// ps.stress of every particle, ghosts included, from ps.grad_v (once per step, not per pair).
template <int D>
void update_deviatoric_stress(ParticleSet<D>& ps, double mu) {
  const auto n = static_cast<long>(ps.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
    ps.stress[i] = deviatoric_stress(ps.grad_v[i], mu);
}

// Reads ps.stress (update_deviatoric_stress).
template <int D>
struct ViscosityBonetLok24 {
  using Acc = Vec<D>;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;                          // 1 / rho_b, computed once per particle (own.hpp)
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return 1.0 / ps.rho[b]; }
  void pair(Acc& a_i, Acc& a_j, Own inv_rho_i, Own inv_rho_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const Vec<D> f = ((ps.stress[i] + ps.stress[j]) * g.gradw) * (inv_rho_i * inv_rho_j);
    a_i += f * ps.m[j];
    a_j -= f * ps.m[i];
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
