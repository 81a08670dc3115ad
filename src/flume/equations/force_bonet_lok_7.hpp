// Pressure force BL (7), variationally consistent with the summation density BL (1):
//   T_a = sum_b m_a m_b (p_a/rho_a^2 + p_b/rho_b^2) grad W_a(x_b).
// Compression positive (methods.md erratum 1): a_a = +T_a/m_a, and with
// grad W_a(x_b) = -grad_{x_a} W(x_a - x_b) this is the familiar
//   a_a = -sum_b m_b (p_a/rho_a^2 + p_b/rho_b^2) grad_a W_ab,
// which pushes compressed particles apart. The pair force is antisymmetric and central:
// m_a a_a gets -f, m_b a_b gets +f with f = m_a m_b (p_a/rho_a^2 + p_b/rho_b^2) grad_a W_ab.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D>
struct ForceBonetLok7 {
  using Acc = Vec<D>;
  static constexpr bool kGradientOnly = true;  // no self pair (own.hpp)
  using Own = double;  // p_b / rho_b^2, computed once per particle (own.hpp)
  ParticleSet<D>& ps;

  Acc init(std::size_t) const { return {}; }
  Own own(std::size_t b) const { return ps.p[b] / (ps.rho[b] * ps.rho[b]); }
  // Central: f = s grad_a W_ab with s = p_a/rho_a^2 + p_b/rho_b^2 (own.hpp, HasRadial).
  static constexpr bool kRadial = true;
  double radial(Own p_rho2_i, Own p_rho2_j, std::size_t, std::size_t, const Pair<D>&) const {
    return p_rho2_i + p_rho2_j;
  }
  void pair(Acc& a_i, Acc& a_j, Own p_rho2_i, Own p_rho2_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    const Vec<D> f = g.gradw * radial(p_rho2_i, p_rho2_j, i, j, g);
    a_i -= f * ps.m[j];
    a_j += f * ps.m[i];
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
