// Summation density with the first-order kernel correction, BL (47)-(52): the density is
// interpolated with the corrected kernel
//   W~_b(x) = W_b(x) alpha(x) [1 + beta(x) . (x - x_b)],                       BL (47)
//   beta(x) = [sum_b V_b (x - x_b) (x) (x - x_b) W_b(x)]^{-1} sum_b V_b (x_b - x) W_b(x),   BL (51)
//   alpha(x) = 1 / sum_b V_b [1 + beta(x) . (x - x_b)] W_b(x),                  BL (52)
// in place of W in BL (1): rho_a = sum_b V_b rho_b W~_b(x_a) = sum_b m_b W~_b(x_a), which
// reproduces any linear density field exactly (BL (49)-(50)). alpha_a and beta_a are a's own, so
// they factor out of the sums:
//   rho_a = alpha_a [sum_b m_b W + beta_a . sum_b m_b (x_a - x_b) W],
//   alpha_a = 1 / [sum_b V_b W + beta_a . sum_b V_b (x_a - x_b) W],
// and one sweep gathers the five sums. V_b = m_b / rho_b takes the densities of the step before
// (see density_summation_shepard_bl53.hpp).
// Where the second-moment matrix of BL (51) cannot be inverted usefully (a particle whose
// neighbours lie on a line), beta_a = 0: the Shepard correction BL (53), which BL (47) reduces
// to. The matrix scales with h^2, so it is judged relative to its own size: smallest singular
// value below kMinRelativeSingularValue times its mean eigenvalue (at a flat free surface both
// directions lose half the kernel and the ratio stays ~1).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/core/singular_value.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

inline constexpr double kMinRelativeSingularValue = 0.1;

template <int D>
struct DensitySummationFirstOrderBL47 {
  struct Acc {
    double mw;    // sum_b m_b W
    Vec<D> mxw;   // sum_b m_b (x_a - x_b) W
    double vw;    // sum_b V_b W
    Vec<D> vxw;   // sum_b V_b (x_a - x_b) W
    Mat<D> vxxw;  // sum_b V_b (x_a - x_b) (x) (x_a - x_b) W
  };
  using Own = double;  // V_b = m_b / rho_b (own.hpp)
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return ps.m[b] / ps.rho[b]; }
  // Seen from b, x_b - x_a = -xij: the first moments change sign, the second does not.
  void pair(Acc& acc_i, Acc& acc_j, Own vol_i, Own vol_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const Vec<D> xw = g.xij * g.w;
    const Mat<D> xxw = outer(xw, g.xij);
    acc_i.mw += ps.m[j] * g.w;
    acc_i.mxw += xw * ps.m[j];
    acc_i.vw += vol_j * g.w;
    acc_i.vxw += xw * vol_j;
    acc_i.vxxw += xxw * vol_j;
    acc_j.mw += ps.m[i] * g.w;
    acc_j.mxw -= xw * ps.m[i];
    acc_j.vw += vol_i * g.w;
    acc_j.vxw -= xw * vol_i;
    acc_j.vxxw += xxw * vol_i;
  }
  void finish(Acc& acc, std::size_t i) const {
    Vec<D> beta;  // BL (51): the first moment sum_b V_b (x_b - x_a) W is -vxw
    const double size = trace(acc.vxxw) / D;
    if (size > 0.0 && singular_value_at_least(acc.vxxw, kMinRelativeSingularValue * size))
      beta = inverse(acc.vxxw) * (-acc.vxw);
    const double alpha = 1.0 / (acc.vw + dot(beta, acc.vxw));  // BL (52)
    ps.rho[i] = alpha * (acc.mw + dot(beta, acc.mxw));
  }
};

}  // namespace flume
