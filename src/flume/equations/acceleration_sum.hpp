// The momentum equation's terms summed in one sweep, BL (6) / W (3.17):
//   a_a = g + sum of the pair terms (pressure force, physical and artificial viscosity).
// Every term gives the pair (i, j) its acceleration shares; here they share one accumulator per
// particle, added to ps.a once at the end, instead of one accumulator (and one finish) per term.
// Each term keeps its own file, formula and finish (ps.a[i] += a) for use on its own.
#pragma once

#include <tuple>
#include <type_traits>

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"

namespace flume {

template <int D, class... Terms>
struct AccelerationSum {
  static_assert((std::is_same_v<typename Terms::Acc, Vec<D>> && ...),
                "every term of the momentum equation accumulates an acceleration");
  using Acc = Vec<D>;
  ParticleSet<D>& ps;
  std::tuple<const Terms&...> terms;

  AccelerationSum(ParticleSet<D>& particles, const Terms&... t) : ps(particles), terms(t...) {}

  Acc init(std::size_t) const { return {}; }
  void pair(Acc& a_i, Acc& a_j, std::size_t i, std::size_t j, const Pair<D>& g) const {
    std::apply([&](const auto&... t) { (t.pair(a_i, a_j, i, j, g), ...); }, terms);
  }
  void finish(Acc& a, std::size_t i) const { ps.a[i] += a; }
};

}  // namespace flume
