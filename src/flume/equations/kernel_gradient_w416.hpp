// The kernel gradient a pair of the thesis's weak schemes uses:
//   plain (W-SPH, W (3.79)-(3.83)):  grad_{x_i} psi_{eps_ij}(x_i - x_j);
//   renormalized (R-SPH, W (4.19)-(4.23)): B_ij grad_{x_i} psi_ij with B_ij = (B_i + B_j) / 2,
//   W (4.16), and B_i = E_i^{-1}, E_i^{ab} = sum_j omega_j (x_j^b - x_i^b) d_a psi_ij W (4.11).
// W's B_i is BL's L_i of BL (45) (methods.md), which the gradient-correction sweep leaves in
// ps.L (corrected_velocity_gradient.hpp, with its fallback to I where E_i cannot be inverted).
// Seen from j, B_ji = B_ij and grad_j psi_ji = -grad_i psi_ij: the gradient is antisymmetric
// in the pair, so forces built on it keep linear momentum (not angular: B_ij G is not central).
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

struct PlainGradient {
  static constexpr bool kRenormalized = false;
  template <int D>
  static Vec<D> of(const ParticleSet<D>&, std::size_t, std::size_t, const Pair<D>& g) {
    return g.gradw;
  }
};

struct RenormalizedGradient {
  static constexpr bool kRenormalized = true;
  template <int D>
  static Vec<D> of(const ParticleSet<D>& ps, std::size_t i, std::size_t j, const Pair<D>& g) {
    return ((ps.L[i] + ps.L[j]) * 0.5) * g.gradw;  // W (4.16)
  }
};

}  // namespace flume
