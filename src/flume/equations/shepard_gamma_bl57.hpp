// Shepard (constant) kernel correction, BL (53)-(54) and the gamma of BL (57), at particle a:
//   S_a = sum_b V_b W_b(x_a),   gamma_a = sum_b V_b grad W_b(x_a) / S_a,   V_b = m_b / rho_b.
// The corrected kernel is W~_b(x_a) = W_b(x_a) / S_a and, with the factor that BL (57) misses
// (methods.md erratum 2), grad W~_b(x_a) = [grad W_b(x_a) - W_b(x_a) gamma_a] / S_a, which gives
// sum_b V_b grad W~_b(x_a) = 0 exactly: the identity CSPH's momentum conservation rests on.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct ShepardGammaBL57 {
  struct Acc {
    double s = 0.0;
    Vec<D> grad;
  };
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  // Seen from b, W is the same and grad W changes sign.
  void pair(Acc& acc_i, Acc& acc_j, std::size_t i, std::size_t j, const Pair<D>& g) const {
    const double vol_j = ps.m[j] / ps.rho[j], vol_i = ps.m[i] / ps.rho[i];
    acc_i.s += vol_j * g.w;
    acc_i.grad += g.gradw * vol_j;
    acc_j.s += vol_i * g.w;
    acc_j.grad -= g.gradw * vol_i;
  }
  void finish(Acc& acc, std::size_t i) const {
    ps.shepard[i] = acc.s;  // > 0: the self term V_a W(0) is always there
    ps.gamma[i] = acc.grad * (1.0 / acc.s);
  }
};

// grad W~_b(x_a) of BL (57) corrected, at particle a with its S_a and gamma_a, from the
// uncorrected grad W_b(x_a) = gradw and W_b(x_a) = w.
template <int D>
Vec<D> corrected_kernel_gradient(const ParticleSet<D>& ps, std::size_t a, const Vec<D>& gradw,
                                 double w) {
  return (gradw - ps.gamma[a] * w) * (1.0 / ps.shepard[a]);
}

}  // namespace flume
