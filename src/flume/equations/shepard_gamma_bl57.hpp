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
  void pair(Acc& acc, std::size_t, const Pair<D>& g) const {
    const double vol = ps.m[g.j] / ps.rho[g.j];
    acc.s += vol * g.w;
    acc.grad += g.gradw * vol;
  }
  void finish(Acc& acc, std::size_t i) const {
    ps.shepard[i] = acc.s;  // > 0: the self term V_a W(0) is always there
    ps.gamma[i] = acc.grad * (1.0 / acc.s);
  }
};

// grad W~_b(x_a) of BL (57) corrected, for the pair (a = i, b = j), from a's S and gamma.
template <int D>
Vec<D> corrected_kernel_gradient(const ParticleSet<D>& ps, std::size_t i, const Pair<D>& g) {
  return (g.gradw - ps.gamma[i] * g.w) * (1.0 / ps.shepard[i]);
}

}  // namespace flume
