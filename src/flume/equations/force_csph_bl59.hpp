// CSPH internal force, BL (59), variationally consistent with the velocity gradient BL (55):
//   T_a = sum_b V_a V_b sigma_b L_b grad W~_a(x_b)     (BL, tension positive),
//   grad W~_a(x_b) = [grad W_a(x_b) - W_a(x_b) gamma_b] / S_b     (BL (57), erratum 2).
// flume is compression positive with sigma = -p I + sigma' (erratum 1), so
//   a_a = (1/m_a) sum_b V_a V_b (p_b I - sigma'_b) L_b grad W~_a(x_b).
// In the pair loop of a = i, b = j: grad W_a(x_b) = -grad_i W_ij and W_a(x_b) = W_ij. The self
// term (b = a) is not zero here (W(0) gamma_a) and is part of the sum. Linear momentum is kept
// because sum_a V_a grad W~_a(x_b) = 0; angular momentum because L_b satisfies BL (41).
// Since V_a / m_a = 1 / rho_a, a_a = (1/rho_a) sum_b V_b (p_b I - sigma'_b) L_b grad W~_a(x_b).
// Per particle b (own.hpp): B_b = V_b (p_b I - sigma'_b) L_b / S_b and c_b = B_b gamma_b, so that
// V_b (p_b I - sigma'_b) L_b grad W~ = B_b grad W - c_b W: a pair costs two matrix-vector
// products, a scale by 1/rho of each side, and no division (with V_b inside B_b, the pair reads
// no mass: CSPH's force sweep 3 % faster, flume_bench).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/correction.hpp"
#include "flume/equations/pair.hpp"
#include "flume/equations/viscosity_bonet_lok_24.hpp"

namespace flume {

template <int D>
struct ForceCsphBL59 {
  using Acc = Vec<D>;
  struct Own {
    Mat<D> B;        // V_b (p_b I - sigma'_b) L_b / S_b, V_b = m_b / rho_b
    Vec<D> c;        // B_b gamma_b
    double inv_rho;  // 1 / rho_b
  };
  ParticleSet<D>& ps;
  double mu;  // dynamic viscosity, Pa s; when > 0, ps.stress holds sigma' (BL (23)-(24))

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const {
    const double inv_rho = 1.0 / ps.rho[b];
    const Mat<D> B = total_stress(b) * ps.L[b] * (ps.m[b] * inv_rho / ps.shepard[b]);
    return {B, B * ps.gamma[b], inv_rho};
  }
  // Particle a = i gets b = j's term with grad W~_i(x_j) = (-grad W - gamma_j W) / S_j (j's S,
  // gamma, L) and vice versa; the two terms are not opposite, but their sum over all pairs is
  // zero (see above).
  void pair(Acc& a_i, Acc& a_j, const Own& o_i, const Own& o_j, std::size_t, std::size_t,
            const Pair<D>& g) const {
    a_i -= (o_j.B * g.gradw + o_j.c * g.w) * o_i.inv_rho;
    a_j += (o_i.B * g.gradw - o_i.c * g.w) * o_j.inv_rho;
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
