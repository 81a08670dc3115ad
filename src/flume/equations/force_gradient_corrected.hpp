// Internal force of the gradient correction alone, BL 4.1, which BL does not give (methods.md
// erratum 9): the variational partner of the corrected velocity gradient BL (43),
//   T_a = sum_b V_a V_b (sigma_a L_a + sigma_b L_b) grad W_a(x_b)     (BL, tension positive).
// Derivation: the internal power sum_a V_a sigma_a : grad v_a with grad v_a of BL (43) is
// sum_a sum_b V_a V_b (v_b - v_a) . sigma_a L_a grad W_b(x_a); its coefficient of v_c, with
// grad W_c(x_b) = -grad W_b(x_c), is the sum above. With L = I it is BL (20) (and (24) for the
// viscous stress). flume is compression positive with sigma = -p I + sigma' (erratum 1):
//   a_a = (1/m_a) sum_b V_a V_b (B_a + B_b) grad W_a(x_b),   B_b = (p_b I - sigma'_b) L_b.
// In the pair loop of a = i, b = j: grad W_i(x_j) = -grad_i W_ij, so i gets
// -m_j/(rho_i rho_j) (B_i + B_j) grad_i W_ij and j the opposite times m_i: antisymmetric (linear
// momentum kept), but not central (angular momentum is kept through BL (41), which L_a
// enforces, not pair by pair).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct ForceGradientCorrected {
  using Acc = Vec<D>;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  struct Own {
    Mat<D> B;        // (p_b I - sigma'_b) L_b
    double inv_rho;  // 1 / rho_b
  };
  ParticleSet<D>& ps;
  double mu;  // dynamic viscosity, Pa s; when > 0, ps.stress holds sigma' (BL (23)-(24))

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const {
    Mat<D> s = Mat<D>::identity() * ps.p[b];
    if (mu > 0.0) s -= ps.stress[b];
    return {s * ps.L[b], 1.0 / ps.rho[b]};
  }
  void pair(Acc& a_i, Acc& a_j, const Own& o_i, const Own& o_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const Vec<D> f = (o_i.B + o_j.B) * g.gradw * (o_i.inv_rho * o_j.inv_rho);
    a_i -= f * ps.m[j];
    a_j += f * ps.m[i];
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
