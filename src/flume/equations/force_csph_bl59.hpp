// CSPH internal force, BL (59), variationally consistent with the velocity gradient BL (55):
//   T_a = sum_b V_a V_b sigma_b L_b grad W~_a(x_b)     (BL, tension positive),
//   grad W~_a(x_b) = [grad W_a(x_b) - W_a(x_b) gamma_b] / S_b     (BL (57), erratum 2).
// flume is compression positive with sigma = -p I + sigma' (erratum 1), so
//   a_a = (1/m_a) sum_b V_a V_b (p_b I - sigma'_b) L_b grad W~_a(x_b).
// In the pair loop of a = i, b = j: grad W_a(x_b) = -grad_i W_ij and W_a(x_b) = W_ij. The self
// term (b = a) is not zero here (W(0) gamma_a) and is part of the sum. Linear momentum is kept
// because sum_a V_a grad W~_a(x_b) = 0; angular momentum because L_b satisfies BL (41).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"
#include "flume/equations/shepard_gamma_bl57.hpp"
#include "flume/equations/viscosity_bonet_lok_24.hpp"

namespace flume {

template <int D>
struct ForceCsphBL59 {
  using Acc = Vec<D>;
  ParticleSet<D>& ps;
  double mu;  // dynamic viscosity, Pa s; when > 0, ps.stress holds sigma' (BL (23)-(24))

  Acc init(std::size_t) const { return {}; }
  // Particle a = i gets b = j's term with grad W~_i(x_j) (j's S, gamma, L) and vice versa; the
  // two terms are not opposite, but their sum over all pairs is zero (see above).
  void pair(Acc& a_i, Acc& a_j, std::size_t i, std::size_t j, const Pair<D>& g) const {
    const double inv_rr = 1.0 / (ps.rho[i] * ps.rho[j]);
    a_i += (total_stress(j) * (ps.L[j] * corrected_kernel_gradient(ps, j, -g.gradw, g.w))) *
           (ps.m[j] * inv_rr);
    a_j += (total_stress(i) * (ps.L[i] * corrected_kernel_gradient(ps, i, g.gradw, g.w))) *
           (ps.m[i] * inv_rr);
  }
  // p_b I - sigma'_b (compression positive).
  Mat<D> total_stress(std::size_t b) const {
    Mat<D> s = Mat<D>::identity() * ps.p[b];
    if (mu > 0.0) s -= ps.stress[b];
    return s;
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
