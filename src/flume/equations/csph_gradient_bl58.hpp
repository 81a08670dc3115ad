// CSPH's per-particle corrections in one sweep: the Shepard value and gamma, BL (53), (57), and
// the velocity gradient and correction matrix, BL (55), (56), (58):
//   S_a = sum_b V_b W_b(x_a),   gamma_a = sum_b V_b grad W_b(x_a) / S_a,
//   grad W~_b(x_a) = [grad W_b(x_a) - W_b(x_a) gamma_a] / S_a        (BL (57), erratum 2),
//   grad v_a = sum_b V_b v_b (x) L_a grad W~_b(x_a),
//   L_a = ( sum_b V_b grad W~_b(x_a) (x) x_b )^{-1}.
// With sum_b V_b grad W~_b(x_a) = 0 (erratum 2) both sums may use differences: v_b - v_a and
// x_b - x_a (same value, less round-off). Writing M_a = sum_b V_b (x_b - x_a) (x) grad W~_b(x_a),
// L_a = M_a^{-T} and grad v_a = [sum_b V_b (v_b - v_a) (x) grad W~_b(x_a)] M_a^{-1}, which is
// exact for any linear velocity field on any particle cloud (BL (41) holds).
// One sweep, not two: grad W~_b(x_a) corrects with a's own S_a and gamma_a only, which factor
// out of the sums over b, so for u_b = v_b - v_a or x_b - x_a
//   sum_b V_b u_b (x) grad W~_b(x_a)
//     = [ sum_b V_b u_b (x) grad W_b(x_a) - (sum_b V_b u_b W_b(x_a)) (x) gamma_a ] / S_a,
// and the sweep gathers the uncorrected sums beside S_a and gamma_a (BL (57) applied in
// finish). The same value as correcting each term (round-off apart); the Shepard sweep's
// kernel evaluations and neighbour walk are saved (CSPH's corrections 24 -> 15 ms a step at
// 1e5 particles, one thread).
// Where M_a is badly conditioned (a corner, the thin tip of a tongue, a lone spray particle: too
// few neighbours to span the space) L_a blows up and with it the force on the neighbours; there
// flume falls back to L_a = I, so that particle has the uncorrected gradient (and the angular
// momentum identity BL (41) does not hold for it). The dam break at a/27 blows up at t = 0.24 s
// with a threshold of 1e-3 and runs stably with 0.3.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

// det M_a below this marks a degenerate neighbourhood: M_a is ~I inside the fluid, ~diag(1, 1/2)
// (det ~0.5) at a flat free surface and ~0.25 at a right-angled corner.
inline constexpr double kCsphMinDeterminant = 0.3;

template <int D>
struct CsphGradientBL58 {
  // The uncorrected sums; with u = v_b - v_a (velocity) or x_b - x_a (moment):
  struct Acc {
    double s;          // sum_b V_b W                  S_a, BL (53)
    Vec<D> gradw;      // sum_b V_b grad W             S_a gamma_a, BL (57)
    Mat<D> grad_dw;    // sum_b V_b (v_b - v_a) (x) grad W
    Vec<D> grad_w;     // sum_b V_b (v_b - v_a) W
    Mat<D> moment_dw;  // sum_b V_b (x_b - x_a) (x) grad W
    Vec<D> moment_w;   // sum_b V_b (x_b - x_a) W
  };
  using Own = double;  // the volume V_b = m_b / rho_b, computed once per particle (own.hpp)
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return ps.m[b] / ps.rho[b]; }
  // Seen from b = j: W is the same, grad W, v_b - v_a and x_b - x_a change sign (so the
  // products with grad W keep theirs).
  void pair(Acc& acc_i, Acc& acc_j, Own vol_i, Own vol_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const Vec<D> dv = ps.v[j] - ps.v[i];
    const Vec<D> dv_i = dv * vol_j, dv_j = dv * vol_i;
    const Vec<D> dx_i = g.xij * (-vol_j), dx_j = g.xij * (-vol_i);
    acc_i.s += vol_j * g.w;
    acc_i.gradw += g.gradw * vol_j;
    acc_i.grad_dw += outer(dv_i, g.gradw);
    acc_i.grad_w += dv_i * g.w;
    acc_i.moment_dw += outer(dx_i, g.gradw);
    acc_i.moment_w += dx_i * g.w;
    acc_j.s += vol_i * g.w;
    acc_j.gradw -= g.gradw * vol_i;
    acc_j.grad_dw += outer(dv_j, g.gradw);
    acc_j.grad_w -= dv_j * g.w;
    acc_j.moment_dw += outer(dx_j, g.gradw);
    acc_j.moment_w -= dx_j * g.w;
  }
  void finish(Acc& acc, std::size_t i) const {
    const double s = acc.s;  // > 0: the self term V_a W(0) is always there
    const double inv_s = 1.0 / s;
    const Vec<D> gamma = acc.gradw * inv_s;  // BL (57)
    ps.shepard[i] = s;
    ps.gamma[i] = gamma;
    // The sums with grad W~_b(x_a) = (grad W - W gamma_a) / S_a.
    const Mat<D> grad = (acc.grad_dw - outer(acc.grad_w, gamma)) * inv_s;
    const Mat<D> moment = (acc.moment_dw - outer(acc.moment_w, gamma)) * inv_s;
    if (determinant(moment) > kCsphMinDeterminant) {
      const Mat<D> inv = inverse(moment);
      ps.L[i] = transpose(inv);
      ps.grad_v[i] = grad * inv;
    } else {
      ps.L[i] = Mat<D>::identity();
      ps.grad_v[i] = grad;
    }
  }
};

// CSPH continuity rate: d rho_a/dt = -rho_a tr(grad v_a) with grad v_a of BL (55), using the L_a
// stored by CsphGradientBL58 and the velocity field `vel` (v^{n+1/2} in the leap-frog).
template <int D>
struct CsphContinuity {
  using Acc = double;
  // Per particle b (own.hpp): K_b = L_b / S_b, k_b = K_b gamma_b and V_b, so that
  // L_b grad W~ = K_b grad W - k_b W.
  struct Own {
    Mat<D> K;
    Vec<D> k;
    double vol;
  };
  ParticleSet<D>& ps;
  const std::vector<Vec<D>>& vel;

  Acc init(std::size_t) const { return 0.0; }
  Own own(std::size_t b) const {
    const Mat<D> K = ps.L[b] * (1.0 / ps.shepard[b]);
    return {K, K * ps.gamma[b], ps.m[b] / ps.rho[b]};
  }
  void pair(Acc& div_i, Acc& div_j, const Own& o_i, const Own& o_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const Vec<D> dv = vel[j] - vel[i];
    const Vec<D> gw_i = o_i.K * g.gradw - o_i.k * g.w;
    const Vec<D> gw_j = o_j.K * (-g.gradw) - o_j.k * g.w;
    div_i += o_j.vol * dot(dv, gw_i);
    div_j -= o_i.vol * dot(dv, gw_j);
  }
  void finish(Acc& div, std::size_t i) const { ps.drho[i] = -ps.rho[i] * div; }
};

}  // namespace flume
