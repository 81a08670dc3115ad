// CSPH velocity gradient and correction matrix, BL (55), (56), (58):
//   grad v_a = sum_b V_b v_b (x) L_a grad W~_b(x_a),
//   L_a = ( sum_b V_b grad W~_b(x_a) (x) x_b )^{-1}.
// With sum_b V_b grad W~_b(x_a) = 0 (erratum 2) both sums may use differences: v_b - v_a and
// x_b - x_a (same value, less round-off). Writing M_a = sum_b V_b (x_b - x_a) (x) grad W~_b(x_a),
// L_a = M_a^{-T} and grad v_a = [sum_b V_b (v_b - v_a) (x) grad W~_b(x_a)] M_a^{-1}, which is
// exact for any linear velocity field on any particle cloud (BL (41) holds).
// Where M_a is badly conditioned (a corner, the thin tip of a tongue, a lone spray particle: too
// few neighbours to span the space) L_a blows up and with it the force on the neighbours; there
// flume falls back to L_a = I, so that particle has the uncorrected gradient (and the angular
// momentum identity BL (41) does not hold for it). The dam break at a/27 blows up at t = 0.24 s
// with a threshold of 1e-3 and runs stably with 0.3.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"
#include "flume/equations/shepard_gamma_bl57.hpp"

namespace flume {

// det M_a below this marks a degenerate neighbourhood: M_a is ~I inside the fluid, ~diag(1, 1/2)
// (det ~0.5) at a flat free surface and ~0.25 at a right-angled corner.
inline constexpr double kCsphMinDeterminant = 0.3;

template <int D>
struct CsphGradientBL58 {
  struct Acc {
    Mat<D> grad;    // sum_b V_b (v_b - v_a) (x) grad W~_b(x_a)
    Mat<D> moment;  // M_a
  };
  using Own = CorrectionFactors<D>;  // V_b, 1/S_b, gamma_b/S_b, once per particle (own.hpp)
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return correction_factors(ps, b); }
  // a = i sees grad W_j(x_i) = gradw, b = j sees grad W_i(x_j) = -gradw; each corrects it with
  // its own S and gamma.
  void pair(Acc& acc_i, Acc& acc_j, const Own& o_i, const Own& o_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const Vec<D> dv = ps.v[j] - ps.v[i];
    const Vec<D> gw_i = o_i.corrected(g.gradw, g.w);
    const Vec<D> gw_j = o_j.corrected(-g.gradw, g.w);
    const double vol_j = o_j.vol, vol_i = o_i.vol;
    acc_i.grad += outer(dv, gw_i) * vol_j;
    acc_i.moment += outer(-g.xij, gw_i) * vol_j;
    acc_j.grad += outer(-dv, gw_j) * vol_i;
    acc_j.moment += outer(g.xij, gw_j) * vol_i;
  }
  void finish(Acc& acc, std::size_t i) const {
    if (determinant(acc.moment) > kCsphMinDeterminant) {
      const Mat<D> inv = inverse(acc.moment);
      ps.L[i] = transpose(inv);
      ps.grad_v[i] = acc.grad * inv;
    } else {
      ps.L[i] = Mat<D>::identity();
      ps.grad_v[i] = acc.grad;
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
