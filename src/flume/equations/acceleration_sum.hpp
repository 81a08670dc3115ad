// The momentum equation's terms summed in one sweep, BL (6) / W (3.17):
//   a_a = g + sum of the pair terms (pressure force, physical and artificial viscosity).
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
  std::tuple<const Terms&...> terms;

  AccelerationSum(ParticleSet<D>& particles, const Terms&... t) : ps(particles), terms(t...) {}

  Acc init(std::size_t) const { return {}; }
  auto own(std::size_t b) const requires(HasOwn<Terms> || ...) {
    return std::apply([&](const auto&... t) { return make_own_pack(own_of(t, b)...); }, terms);
  }
  void pair(Acc& a_i, Acc& a_j, std::size_t i, std::size_t j, const Pair<D>& g) const
      requires(!(HasOwn<Terms> || ...)) {
    pair(a_i, a_j, OwnPack<OwnOf<Terms>...>{}, OwnPack<OwnOf<Terms>...>{}, i, j, g);
  }
  // The terms add to local sums, and each accumulator is written once: a write to a_j between
  // two terms would make the compiler reload everything the next term reads of the particles.
  void pair(Acc& a_i, Acc& a_j, const OwnPack<OwnOf<Terms>...>& o_i,
            const OwnPack<OwnOf<Terms>...>& o_j, std::size_t i, std::size_t j,
            const Pair<D>& g) const {
    Acc sum_i{}, sum_j{};
    [&]<std::size_t... K>(std::index_sequence<K...>) {
      (pair_of(std::get<K>(terms), sum_i, sum_j, own_get<K>(o_i), own_get<K>(o_j), i, j, g), ...);
    }
    (std::index_sequence_for<Terms...>{});
    a_i += sum_i;
    a_j += sum_j;
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
