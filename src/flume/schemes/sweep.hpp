// The loop driver: one fused sweep over the neighbours of every real particle, running a group
// of equations (PySPH's Group). Each equation has the fixed shape
//   Acc init(i);  void pair(Acc&, i, const Pair<D>&);  void finish(Acc&, i);
// and knows nothing of loops or threads. The loop is gather style: particle i sums its own
// neighbours into a private accumulator and writes only to index i, so results do not depend
// on the thread count. Equations are template parameters, so the compiler inlines them.
#pragma once

#include <tuple>

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"
#include "flume/neighbors/neighbor_list.hpp"

namespace flume {

template <int D, class Kernel, class... Eqs>
void sweep(const NeighborList& nl, const ParticleSet<D>& ps, Eqs&... eqs) {
  const auto n = static_cast<long>(nl.queries());
  const double support = Kernel::support;
#pragma omp parallel for schedule(static)
  for (long ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    std::tuple<typename Eqs::Acc...> acc{eqs.init(i)...};
    for (const auto jj : nl.of(i)) {
      Pair<D> g;
      g.j = jj;
      g.xij = ps.x[i] - ps.x[jj];
      g.h = 0.5 * (ps.h[i] + ps.h[jj]);
      g.r = norm(g.xij);
      if (g.r >= support * g.h) continue;
      g.w = Kernel::w(g.r, g.h);
      if (g.r > 0.0) g.gradw = g.xij * (Kernel::dwdr(g.r, g.h) / g.r);
      std::apply([&](auto&... a) { (eqs.pair(a, i, g), ...); }, acc);
    }
    std::apply([&](auto&... a) { (eqs.finish(a, i), ...); }, acc);
  }
}

// A per-particle pass over the real particles (equation of state, stresses, body forces).
template <class F>
void for_each_real(std::size_t n_real, F&& f) {
  const auto n = static_cast<long>(n_real);
#pragma omp parallel for schedule(static)
  for (long ii = 0; ii < n; ++ii)
    f(static_cast<std::size_t>(ii));
}

}  // namespace flume
