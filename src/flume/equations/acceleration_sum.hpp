// The momentum equation's terms summed in one sweep, BL (6) / W (3.17):
//   a_a = g + sum of the pair terms (pressure force, physical and artificial viscosity).
// It writes the whole of a_a, the body force g included, in its finish.
// Every term gives the pair (i, j) its acceleration shares; here they share one accumulator per
// particle, added to ps.a once at the end, instead of one accumulator (and one finish) per term.
// Each term keeps its own file, formula and finish (ps.a[i] += a) for use on its own. The terms'
// per-particle factors (own.hpp), if any, travel together as one OwnPack.
#pragma once

#include <tuple>
#include <type_traits>
#include <utility>

#include "flume/core/particle_set.hpp"
#include "flume/equations/own.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

namespace detail {
template <bool Any, class Owns>
struct OwnDeclaration {};
template <class Owns>
struct OwnDeclaration<true, Owns> {
  using Own = Owns;
};
}  // namespace detail

template <int D, class... Terms>
struct AccelerationSum : detail::OwnDeclaration<(HasOwn<Terms> || ...), OwnPack<OwnOf<Terms>...>> {
  static_assert((std::is_same_v<typename Terms::Acc, Vec<D>> && ...),
                "every term of the momentum equation accumulates an acceleration");
  using Acc = Vec<D>;
  static constexpr bool kGradientOnly = (gradient_only<Terms>() && ...);
  ParticleSet<D>& ps;
  Vec<D> body;  // g = F_a / m_a, the external force of BL (6), m/s^2
  std::tuple<const Terms&...> terms;

  AccelerationSum(ParticleSet<D>& particles, const Vec<D>& g, const Terms&... t)
      : ps(particles), body(g), terms(t...) {}

  Acc init(std::size_t) const { return {}; }
  auto own(std::size_t b) const requires(HasOwn<Terms> || ...) {
    return std::apply([&](const auto&... t) { return make_own_pack(own_of(t, b)...); }, terms);
  }
  void pair(Acc& a_i, Acc& a_j, std::size_t i, std::size_t j, const Pair<D>& g) const
      requires(!(HasOwn<Terms> || ...)) {
    pair(a_i, a_j, OwnPack<OwnOf<Terms>...>{}, OwnPack<OwnOf<Terms>...>{}, i, j, g);
  }
  // The radial terms (own.hpp, HasRadial) add their scalars s, and grad W is multiplied once:
  //   a_i -= m_j (s_1 + s_2 + ...) grad W,  a_j += m_i (s_1 + s_2 + ...) grad W.
  // The other terms add to local sums. Each accumulator is written once: a write to a_j between
  // two terms would make the compiler reload everything the next term reads of the particles.
  void pair(Acc& a_i, Acc& a_j, const OwnPack<OwnOf<Terms>...>& o_i,
            const OwnPack<OwnOf<Terms>...>& o_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    constexpr bool radial[] = {HasRadial<Terms>...};
    constexpr std::size_t n_radial = (std::size_t{HasRadial<Terms>} + ...);
    constexpr std::size_t first_radial = [&] {
      std::size_t k = 0;
      while (k < sizeof...(Terms) && !radial[k])
        ++k;
      return k;
    }();
    Acc sum_i{}, sum_j{};
    double s = 0.0;
    [&]<std::size_t... K>(std::index_sequence<K...>) {
      auto term = [&]<std::size_t T>(std::integral_constant<std::size_t, T>) {
        const auto& t = std::get<T>(terms);
        if constexpr (!HasRadial<std::remove_cvref_t<decltype(t)>>)
          pair_of(t, sum_i, sum_j, own_get<T>(o_i), own_get<T>(o_j), i, j, g);
        else if constexpr (T == first_radial)
          s = radial_of(t, own_get<T>(o_i), own_get<T>(o_j), i, j, g);
        else
          s += radial_of(t, own_get<T>(o_i), own_get<T>(o_j), i, j, g);
      };
      (term(std::integral_constant<std::size_t, K>{}), ...);
    }
    (std::index_sequence_for<Terms...>{});
    if constexpr (n_radial == sizeof...(Terms)) {
      const Vec<D> f = g.gradw * s;
      a_i -= f * ps.m[j];
      a_j += f * ps.m[i];
    } else {
      if constexpr (n_radial > 0) {
        const Vec<D> f = g.gradw * s;
        sum_i -= f * ps.m[j];
        sum_j += f * ps.m[i];
      }
      a_i += sum_i;
      a_j += sum_j;
    }
  }
  // a_a = g + the internal terms: the whole acceleration, so no pass of its own sets a_a = g.
  void finish(Acc& a, std::size_t i) const { ps.a[i] = body + a; }
};

}  // namespace flume
