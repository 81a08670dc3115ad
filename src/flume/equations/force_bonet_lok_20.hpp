// Pressure force BL (20) = W (3.80), variationally consistent with the continuity density BL (4):
//   T_a = sum_b V_a V_b (p_a + p_b) grad W_a(x_b),   V = m/rho.
// Compression positive (methods.md erratum 1): a_a = +T_a/m_a, i.e.
//   a_a = -sum_b m_b/(rho_a rho_b) (p_a + p_b) grad_a W_ab.
// Used with the summation density BL (1) it is the "+" form of BL (8): the inconsistent pair of
// BL Fig 10. The pair force is antisymmetric and central: a gets -m_b f, b gets +m_a f with
// f = (p_a + p_b)/(rho_a rho_b) grad_a W_ab.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct ForceBonetLok20 {
  using Acc = Vec<D>;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;                          // 1 / rho_b, computed once per particle (own.hpp)
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return 1.0 / ps.rho[b]; }
  // Central: f = s grad_a W_ab with s = (p_a + p_b) / (rho_a rho_b) (own.hpp, HasRadial).
  static constexpr bool kRadial = true;
  double radial(Own inv_rho_i, Own inv_rho_j, std::size_t i, std::size_t j, const Pair<D>&) const {
    return (ps.p[i] + ps.p[j]) * (inv_rho_i * inv_rho_j);
  }
  void pair(Acc& a_i, Acc& a_j, Own inv_rho_i, Own inv_rho_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const Vec<D> f = g.gradw * radial(inv_rho_i, inv_rho_j, i, j, g);
    a_i -= f * ps.m[j];
    a_j += f * ps.m[i];
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
