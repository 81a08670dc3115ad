// The corrections of BL section 4 that act on the kernel gradient of a continuity scheme, as one
// corrected gradient G_ab (what a uses in place of grad W_b(x_a)):
//   gradient, BL (42):        G_ab = L_a grad W_b(x_a)                          L_a of BL (45)
//   shepard,  BL (53), (57):  G_ab = grad W~_b(x_a) = [grad W_b(x_a) - W_b(x_a) gamma_a] / S_a
//   mixed,    BL (56):        G_ab = L_a grad W~_b(x_a)                         L_a of BL (58)
// (BL (57) with the factor of methods.md erratum 2.) Each is G_ab = K_a grad W_b(x_a) - k_a
// W_b(x_a) with per-particle K_a (a matrix) and k_a (a vector), so that the density rate and the
// force read one form for the three:
//   K_a = L_a, k_a = 0 (gradient);  I / S_a, gamma_a / S_a (shepard);  L_a / S_a, L_a gamma_a / S_a
//   (mixed). The shepard correction keeps L_a = I.
#pragma once

#include "flume/core/particle_set.hpp"

namespace flume {

enum class Correction { gradient, shepard, mixed };

// Whether the correction divides by the Shepard value S_a (the kernel correction, BL (53)).
constexpr bool corrects_kernel(Correction c) {
  return c != Correction::gradient;
}
// Whether it inverts the moment matrix of BL (41) (the gradient correction, BL (45) or (58)).
constexpr bool corrects_gradient(Correction c) {
  return c != Correction::shepard;
}

// K_b and k_b of particle b, from the fields its correction sweep left (S_b, gamma_b, L_b).
template <int D>
struct GradientFactors {
  Mat<D> K;
  Vec<D> k;
};
template <Correction C, int D>
GradientFactors<D> correction_factors(const ParticleSet<D>& ps, std::size_t b) {
  if constexpr (!corrects_kernel(C)) {
    return {ps.L[b], Vec<D>{}};
  } else {
    const double inv_s = 1.0 / ps.shepard[b];
    const Mat<D> K = ps.L[b] * inv_s;
    return {K, K * ps.gamma[b]};
  }
}

}  // namespace flume
