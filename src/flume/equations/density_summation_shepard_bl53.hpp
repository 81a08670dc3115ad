// Summation density with the Shepard (constant) kernel correction, BL (53)-(54): the density is
// interpolated with W~_b(x) = W_b(x) / sum_c V_c W_c(x) in place of W in BL (1),
//   rho_a = sum_b V_b rho_b W~_b(x_a) = sum_b m_b W_b(x_a) / sum_b V_b W_b(x_a),
// which reproduces a constant density exactly, near a free surface too (where BL (1) reads low
// because half the kernel is empty). V_b = m_b / rho_b takes the densities of the step before
// (the start's, on the first step): the correction is the ratio of two sums over the same
// neighbours, the usual explicit form of this interpolation.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct DensitySummationShepardBL53 {
  struct Acc {
    double mw;  // sum_b m_b W_b(x_a), BL (1)
    double vw;  // sum_b V_b W_b(x_a), the denominator of BL (53)
  };
  using Own = double;  // V_b = m_b / rho_b (own.hpp)
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return ps.m[b] / ps.rho[b]; }
  // W is the same seen from either side.
  void pair(Acc& acc_i, Acc& acc_j, Own vol_i, Own vol_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    acc_i.mw += ps.m[j] * g.w;
    acc_i.vw += vol_j * g.w;
    acc_j.mw += ps.m[i] * g.w;
    acc_j.vw += vol_i * g.w;
  }
  // vw > 0: the self term V_a W(0) is always there.
  void finish(Acc& acc, std::size_t i) const { ps.rho[i] = acc.mw / acc.vw; }
};

}  // namespace flume
