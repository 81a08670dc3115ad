// Density rate of weak SPH, W (3.79), and of R-SPH, W (4.19), with the sign corrected
// (methods.md erratum 4: as printed they lower the density under compression):
//   d rho_i/dt = -sum_j (m_j rho_i p_j) / (rho_j p_i) (u_j - u_i) . G_ij,
// G_ij = grad_i psi_ij (W-SPH) or B_ij grad_i psi_ij (R-SPH) (kernel_gradient_w416.hpp). It
// divides by p_i: for a liquid (Tait) p_j/p_i is replaced by 1 (methods.md erratum 6), which
// is BL (4)'s d rho_i/dt = -rho_i sum_j V_j (u_j - u_i) . grad_i psi_ij.
// With q = p (gas) or 1 (liquid), (u_j - u_i) . G_ij is the same seen from j: i gets
// m_j q_j / rho_j times it, j gets m_i q_i / rho_i times it; finish multiplies by -rho_i / q_i.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/kernel_gradient_w416.hpp"
#include "flume/equations/pair.hpp"
#include "flume/equations/smoothing_length_w222.hpp"

namespace flume {

template <int D, class Gradient = PlainGradient>
struct DensityRateWeakW379 {
  using Acc = double;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;                          // q_b / rho_b
  ParticleSet<D>& ps;
  const std::vector<Vec<D>>& vel;
  bool gas;  // q = p (gas) or 1 (liquid)

  double q(std::size_t b) const { return gas ? ps.p[b] : 1.0; }
  Acc init(std::size_t) const { return 0.0; }
  Own own(std::size_t b) const { return q(b) / ps.rho[b]; }
  void pair(Acc& s_i, Acc& s_j, Own o_i, Own o_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const double s = dot(vel[j] - vel[i], Gradient::of(ps, i, j, g));
    s_i += ps.m[j] * o_j * s;
    s_j += ps.m[i] * o_i * s;
  }
  void finish(Acc& s, std::size_t i) const {
    ps.drho[i] = -ps.rho[i] / q(i) * s;
    smoothing_length_rate_w222(ps, i);
  }
};

}  // namespace flume
