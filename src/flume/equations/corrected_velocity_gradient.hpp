// The corrections' per-particle sweep (correction.hpp): the Shepard value and gamma, BL (53),
// (57), the correction matrix L and the corrected velocity gradient:
//   S_a = sum_b V_b W_b(x_a),   gamma_a = sum_b V_b grad W_b(x_a) / S_a,
//   grad W~_b(x_a) = [grad W_b(x_a) - W_b(x_a) gamma_a] / S_a        (BL (57), erratum 2),
//   gradient correction, BL (43), (45):
//     grad v_a = sum_b V_b (v_b - v_a) (x) L_a grad W_b(x_a),
//     L_a = ( sum_b V_b grad W_b(x_a) (x) (x_b - x_a) )^{-1};
//   mixed (CSPH), BL (55), (56), (58):
//     grad v_a = sum_b V_b v_b (x) L_a grad W~_b(x_a),
//     L_a = ( sum_b V_b grad W~_b(x_a) (x) x_b )^{-1};
//   shepard, BL (53), (57): grad v_a = sum_b V_b (v_b - v_a) (x) grad W~_b(x_a), L_a = I.
// With sum_b V_b grad W~_b(x_a) = 0 (erratum 2) the mixed sums may use differences: v_b - v_a and
// x_b - x_a (same value, less round-off). Writing M_a = sum_b V_b (x_b - x_a) (x) G_b(x_a) (the
// matrix of BL (41), G the scheme's gradient before L), L_a = M_a^{-T} and
// grad v_a = [sum_b V_b (v_b - v_a) (x) G_b(x_a)] M_a^{-1}, exact for any linear velocity field
// on any particle cloud (BL (41) holds).
// One sweep: grad W~_b(x_a) corrects with a's own S_a and gamma_a only, which factor out of the
// sums over b, so for u_b = v_b - v_a or x_b - x_a
//   sum_b V_b u_b (x) grad W~_b(x_a)
//     = [ sum_b V_b u_b (x) grad W_b(x_a) - (sum_b V_b u_b W_b(x_a)) (x) gamma_a ] / S_a,
// and the sweep gathers the uncorrected sums beside S_a and gamma_a (BL (57) applied in finish).
// The same value as correcting each term (round-off apart), without a sweep for S and gamma.
// Where M_a cannot be inverted usefully (a lone spray particle, the thin tip of a tongue: too
// few neighbours to span the space) L_a blows up and with it the force on the neighbours. The
// usual remedy (Bonet & Lok's successors, Oger et al. 2007) is to drop the correction there:
// flume falls back to L_a = I where the smallest singular value of M_a is below
// kMinSingularValue (singular_value.hpp says why not the determinant). With the Shepard factor
// (mixed) M_a is ~I inside the fluid and keeps sigma_min ~1/2 at a flat free surface, a
// right-angled corner or a 3D edge; without it (gradient) sigma_min is 1/2 at a flat surface
// and 0.09 at a right-angled corner (eigenvalues 1/4 -+ 1/(2 pi) of the quarter kernel). The
// threshold 0.05 keeps the correction, and BL (41), at all of these; a neighbourhood that does
// not span the space (neighbours on a line) has sigma_min -> 0. Measured: the dam break
// (cases/dam_break.toml) runs stably with all three corrections at 0.05, where a determinant
// floor of 1e-3 let it blow up; the old floor det M > 0.3 dropped the correction at 6-87 of
// the 1176 particles of a jittered drop.
#pragma once

#include <type_traits>

#include "flume/core/particle_set.hpp"
#include "flume/core/singular_value.hpp"
#include "flume/equations/correction.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

// sigma_min(M_a) below this: M_a is taken as unusable and L_a = I (see above).
inline constexpr double kMinSingularValue = 0.05;

// Whether the correction matrix M_a of BL (41) is inverted (L_a = M_a^{-T}).
template <int D>
bool correction_usable(const Mat<D>& moment) {
  return singular_value_at_least(moment, kMinSingularValue);
}

// The sums the sweep gathers, in parts, so that a sweep carries only what its finish uses
// (every number of an accumulator costs a load, an add and a store for each pair's j):
// the moment matrix always; S_a, gamma_a and the W moment with the kernel correction; the
// velocity sums only when the velocity gradient is wanted (a viscous stress).
// With u = v_b - v_a (velocity) or x_b - x_a (moment):
template <int D>
struct MomentSums {
  SymMat<D> moment_dw;  // sum_b V_b (x_b - x_a) (x) grad W (symmetric: grad W is along x_ab)
};
template <int D>
struct KernelSums {
  double s;         // sum_b V_b W                  S_a, BL (53)
  Vec<D> gradw;     // sum_b V_b grad W             S_a gamma_a, BL (57)
  Vec<D> moment_w;  // sum_b V_b (x_b - x_a) W
};
template <int D>
struct VelocitySums {
  Mat<D> grad_dw;  // sum_b V_b (v_b - v_a) (x) grad W
};
template <int D>
struct KernelVelocitySums {
  Vec<D> grad_w;  // sum_b V_b (v_b - v_a) W
};
// The parts left out (distinct empty bases, so that they take no room).
struct NoKernelSums {};
struct NoVelocitySums {};
struct NoKernelVelocitySums {};

// Velocity: whether the sweep also gives grad v_a (ps.grad_v); without it only S_a, gamma_a
// and L_a are computed.
template <int D, Correction C, bool Velocity>
struct CorrectedVelocityGradient {
  static constexpr bool kKernel = corrects_kernel(C);
  struct Acc
      : MomentSums<D>,
        std::conditional_t<kKernel, KernelSums<D>, NoKernelSums>,
        std::conditional_t<Velocity, VelocitySums<D>, NoVelocitySums>,
        std::conditional_t<kKernel && Velocity, KernelVelocitySums<D>, NoKernelVelocitySums> {};
  using Own = double;  // the volume V_b = m_b / rho_b, computed once per particle (own.hpp)
  // Without the kernel correction every term carries grad W: no self pair (own.hpp).
  static constexpr bool kGradientOnly = !kKernel;
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return ps.m[b] / ps.rho[b]; }
  // Seen from b = j: W is the same, grad W, v_b - v_a and x_b - x_a change sign (so the
  // products with grad W keep theirs).
  void pair(Acc& acc_i, Acc& acc_j, Own vol_i, Own vol_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    // (x_b - x_a) (x) grad W = -x_ij (x) grad W for b = j and for b = i.
    const SymMat<D> xx = outer_parallel(g.xij, g.gradw);
    acc_i.moment_dw -= xx * vol_j;
    acc_j.moment_dw -= xx * vol_i;
    if constexpr (kKernel) {
      acc_i.s += vol_j * g.w;
      acc_i.gradw += g.gradw * vol_j;
      acc_i.moment_w -= g.xij * (vol_j * g.w);
      acc_j.s += vol_i * g.w;
      acc_j.gradw -= g.gradw * vol_i;
      acc_j.moment_w += g.xij * (vol_i * g.w);
    }
    if constexpr (Velocity) {
      const Vec<D> dv = ps.v[j] - ps.v[i];
      const Vec<D> dv_i = dv * vol_j, dv_j = dv * vol_i;
      acc_i.grad_dw += outer(dv_i, g.gradw);
      acc_j.grad_dw += outer(dv_j, g.gradw);
      if constexpr (kKernel) {
        acc_i.grad_w += dv_i * g.w;
        acc_j.grad_w -= dv_j * g.w;
      }
    }
  }
  void finish(Acc& acc, std::size_t i) const {
    Mat<D> moment = acc.moment_dw.full();
    [[maybe_unused]] Mat<D> grad;
    if constexpr (Velocity) grad = acc.grad_dw;
    if constexpr (kKernel) {
      const double s = acc.s;  // > 0: the self term V_a W(0) is always there
      const double inv_s = 1.0 / s;
      const Vec<D> gamma = acc.gradw * inv_s;  // BL (57)
      ps.shepard[i] = s;
      ps.gamma[i] = gamma;
      // The sums with grad W~_b(x_a) = (grad W - W gamma_a) / S_a.
      moment = (moment - outer(acc.moment_w, gamma)) * inv_s;
      if constexpr (Velocity) grad = (grad - outer(acc.grad_w, gamma)) * inv_s;
    }
    // How far BL (41) is from holding before L_a: |M_a - I| (Frobenius), for the snapshots.
    const Mat<D> off = moment - Mat<D>::identity();
    ps.bl41_deviation[i] = std::sqrt(ddot(off, off));
    if (corrects_gradient(C) && correction_usable(moment)) {
      const Mat<D> inv = inverse(moment);
      ps.L[i] = transpose(inv);
      if constexpr (Velocity) ps.grad_v[i] = grad * inv;
    } else {
      ps.L[i] = Mat<D>::identity();
      if constexpr (Velocity) ps.grad_v[i] = grad;
    }
  }
};

// Corrected continuity rate: d rho_a/dt = -rho_a tr(grad v_a) with the corrected gradient of
// BL (43) / (55), using the S, gamma and L left by CorrectedVelocityGradient and the velocity
// field `vel` (v^{n+1/2} in the leap-frog): tr(grad v_a) = sum_b V_b (v_b - v_a) . G_ab.
template <int D, Correction C>
struct CorrectedContinuity {
  using Acc = double;
  // Per particle b (own.hpp): K_b, k_b (correction.hpp) and V_b, so that
  // G_ba = K_b grad W_a(x_b) - k_b W.
  struct Own {
    Mat<D> K;
    Vec<D> k;
    double vol;
  };
  ParticleSet<D>& ps;
  const std::vector<Vec<D>>& vel;

  Acc init(std::size_t) const { return 0.0; }
  Own own(std::size_t b) const {
    const auto f = correction_factors<C>(ps, b);
    return {f.K, f.k, ps.m[b] / ps.rho[b]};
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
