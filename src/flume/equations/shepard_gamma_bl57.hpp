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
  using Own = double;  // the volume V_b = m_b / rho_b, computed once per particle (own.hpp)
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return ps.m[b] / ps.rho[b]; }
  // Seen from b, W is the same and grad W changes sign.
  void pair(Acc& acc_i, Acc& acc_j, Own vol_i, Own vol_j, std::size_t, std::size_t,
            const Pair<D>& g) const {
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
// uncorrected grad W_b(x_a) and W_b(x_a): what it needs of particle a is computed once per
// particle (own.hpp), with a's volume V_a = m_a / rho_a:
//   grad W~_b(x_a) = grad W_b(x_a) (1/S_a) - (gamma_a/S_a) W_b(x_a).
template <int D>
struct CorrectionFactors {
  double vol;
  double inv_s;
  Vec<D> gamma_s;
  Vec<D> corrected(const Vec<D>& gradw, double w) const { return gradw * inv_s - gamma_s * w; }
};
template <int D>
CorrectionFactors<D> correction_factors(const ParticleSet<D>& ps, std::size_t a) {
  const double inv_s = 1.0 / ps.shepard[a];
  return {ps.m[a] / ps.rho[a], inv_s, ps.gamma[a] * inv_s};
}

}  // namespace flume
