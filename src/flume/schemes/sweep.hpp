// The loop driver: one fused sweep over every interacting pair of particles, running a group of
// equations (PySPH's Group). The driver owns loops, threads, pair symmetry and the geometry; an
// equation has the fixed shape (docs/adding_an_equation.md)
//   using Acc = ...;                    what one particle accumulates (double, Vec, Mat, struct)
//   Acc init(i);                        its starting value
//   void pair(Acc& ai, Acc& aj, i, j, const Pair<D>& g);   both particles' shares of pair (i, j)
//   void finish(Acc& a, i);             turns the sum into particle i's fields
// and knows nothing of loops or threads.
// Each pair of real particles is visited once (a half stencil of cells: the rest of i's own cell
// and the cell after it along x, then the rows of cells ahead), and the equation gives i and j
// their shares. A pair with a ghost j is visited from the real side only, with a scratch aj that
// is thrown away (ghosts are copies refreshed from their sources). The self pair (i, i) is
// visited once with r = 0, W = W(0), grad W = 0 and a scratch aj.
// Threads: the cell layers along the slowest axis are cut into slabs; a pair touches the
// accumulators of its own layer and the next only, so the even slabs run in parallel, then the
// odd ones. Every accumulator then receives its terms in an order fixed by the positions alone:
// results are bit-identical for any thread count.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <utility>

#include "flume/core/particle_set.hpp"
#include "flume/equations/pair.hpp"
#include "flume/neighbors/cell_grid.hpp"
#include "flume/schemes/sweep_workspace.hpp"
#include "flume/sim/phase_clock.hpp"

namespace flume {

// What a sweep needs besides the particles: the cell grid of this step, scratch arrays, the
// common smoothing length when every particle has the same one (else 0), and the clock that
// times each sweep (may be null).
template <int D>
struct SweepContext {
  const CellGrid<D>& grid;
  SweepWorkspace& work;
  double uniform_h = 0.0;
  PhaseClock* clock = nullptr;
};

namespace detail {

// Slot of the I-th accumulator among those of the same type before it, so that two equations
// with the same Acc type get different buffers.
template <std::size_t I, class... Accs>
constexpr std::size_t same_type_slot() {
  using T = std::tuple_element_t<I, std::tuple<Accs...>>;
  std::size_t n = 0;
  std::size_t k = 0;
  ((n += (k++ < I && std::is_same_v<Accs, T>) ? 1 : 0), ...);
  return n;
}

constexpr int kSlabLayers = 2;  // cell layers per slab (>= 1: a pair reaches one layer ahead)

// 3^(D-1) cell-row centres around a cell, as offsets (the row along x is [centre-1, centre+1]);
// the first (3^(D-1) - 1)/2 are the rows ahead of the cell (lexicographically after it, the
// slowest axis first), the middle one is the cell's own row.
template <int D>
struct RowOffsets {
  static constexpr int kRows = D == 1 ? 1 : D == 2 ? 3 : 9;
  static constexpr int kAhead = (kRows - 1) / 2;
  std::array<std::ptrdiff_t, kRows> all{};  // ahead rows first, then the own row, then behind

  explicit RowOffsets(const std::array<std::size_t, D>& strides) {
    int ahead = 0, behind = kAhead + 1;
    for (int r = 0; r < kRows; ++r) {
      // digits of r in base 3 over the axes 1..D-1, each -1, 0 or +1
      int rest = r;
      std::ptrdiff_t off = 0;
      int sign = 0;  // sign of the first nonzero offset from the slowest axis
      std::array<int, 3> o{};
      for (int k = 1; k < D; ++k) {
        o[static_cast<std::size_t>(k)] = rest % 3 - 1;
        rest /= 3;
      }
      for (int k = D - 1; k >= 1; --k) {
        off += o[static_cast<std::size_t>(k)] * static_cast<std::ptrdiff_t>(strides[k]);
        if (sign == 0) sign = o[static_cast<std::size_t>(k)];
      }
      if (sign > 0)
        all[static_cast<std::size_t>(ahead++)] = off;
      else if (sign < 0)
        all[static_cast<std::size_t>(behind++)] = off;
      else
        all[static_cast<std::size_t>(kAhead)] = off;
    }
  }
};

template <int D, class Kernel, bool UniformH, class EqTuple, class AccTuple, std::size_t... I>
void sweep_pairs(const SweepContext<D>& ctx, const ParticleSet<D>& ps, EqTuple& eqs, AccTuple& acc,
                 std::index_sequence<I...>) {
  using Accs = std::tuple<std::remove_pointer_t<std::tuple_element_t<I, AccTuple>>...>;
  const CellGrid<D>& grid = ctx.grid;
  const std::size_t layer = grid.strides()[D - 1];
  const long layers = static_cast<long>(grid.dims()[D - 1]);
  const long slabs = (layers + kSlabLayers - 1) / kSlabLayers;
  const RowOffsets<D> rows(grid.strides());
  const double h0 = ctx.uniform_h;
  const double cut0 = Kernel::support * h0;
  const double cut2_0 = cut0 * cut0;
  const auto* x = ps.x.data();
  const auto* hs = ps.h.data();

  // Adds pair (i, j) to ai and aj when j is within the support of the pair smoothing length.
  auto visit = [&](std::size_t i, std::size_t j, Accs& ai, auto&& aj_of) {
    Pair<D> g;
    g.xij = x[i] - x[j];
    const double r2 = norm2(g.xij);
    double h = h0, cut2 = cut2_0;
    if constexpr (!UniformH) {
      h = 0.5 * (hs[i] + hs[j]);
      cut2 = Kernel::support * h * Kernel::support * h;
    }
    if (!(r2 < cut2)) return;
    g.r = std::sqrt(r2);
    g.h = h;
    g.w = Kernel::w(g.r, h);
    if (g.r > 0.0) g.gradw = g.xij * (Kernel::dwdr(g.r, h) / g.r);
    (std::get<I>(eqs).pair(std::get<I>(ai), aj_of(std::integral_constant<std::size_t, I>{}), i, j,
                           g),
     ...);
  };

  for (int phase = 0; phase < 2; ++phase) {
#pragma omp for schedule(dynamic, 1)
    for (long s = phase; s < slabs; s += 2) {
      const std::size_t c_begin = static_cast<std::size_t>(s) * kSlabLayers * layer;
      const std::size_t c_end = std::min(static_cast<std::size_t>(s + 1) * kSlabLayers,
                                         static_cast<std::size_t>(layers)) *
                                layer;
      for (std::size_t c = c_begin; c < c_end; ++c) {
        const std::size_t b = grid.real_begin(c), e = grid.real_begin(c + 1);
        if (b == e) continue;
        for (std::size_t i = b; i < e; ++i) {
          Accs ai{std::get<I>(acc)[i]...};
          Accs scratch{};
          auto to_scratch = [&](auto k) -> decltype(auto) {
            return std::get<decltype(k)::value>(scratch);
          };
          auto to_real = [&](std::size_t j) {
            return [&acc, j](auto k) -> decltype(auto) {
              return std::get<decltype(k)::value>(acc)[j];
            };
          };
          {  // the self pair
            Pair<D> g0;
            g0.h = hs[i];
            g0.w = Kernel::w(0.0, hs[i]);
            (std::get<I>(eqs).pair(std::get<I>(ai), std::get<I>(scratch), i, i, g0), ...);
          }
          // The rest of the own cell and the cell after it along x: one run.
          const std::size_t own_end = grid.real_begin(c + 2);
          for (std::size_t j = i + 1; j < own_end; ++j)
            visit(i, j, ai, to_real(j));
          for (int r = 0; r < RowOffsets<D>::kAhead; ++r) {
            const std::size_t cr =
                c + static_cast<std::size_t>(rows.all[static_cast<std::size_t>(r)]);
            const std::size_t jb = grid.real_begin(cr - 1), je = grid.real_begin(cr + 2);
            for (std::size_t j = jb; j < je; ++j)
              visit(i, j, ai, to_real(j));
          }
          for (int r = 0; r < RowOffsets<D>::kRows; ++r) {
            const std::size_t cr =
                c + static_cast<std::size_t>(rows.all[static_cast<std::size_t>(r)]);
            const std::size_t jb = grid.ghost_begin(cr - 1), je = grid.ghost_begin(cr + 2);
            for (std::size_t j = jb; j < je; ++j)
              visit(i, j, ai, to_scratch);
          }
          ((std::get<I>(acc)[i] = std::get<I>(ai)), ...);
        }
      }
    }
  }
}

template <int D, class Kernel, class... Eqs, std::size_t... I>
void sweep_group(const SweepContext<D>& ctx, const ParticleSet<D>& ps,
                 std::index_sequence<I...> seq, Eqs&... eqs) {
  const std::size_t n = ps.n_real;
  std::tuple<typename Eqs::Acc*...> acc{
      ctx.work.template buffer<typename Eqs::Acc>(same_type_slot<I, typename Eqs::Acc...>(), n)
          .data()...};
  std::tuple<Eqs&...> eqt{eqs...};
  const auto nn = static_cast<long>(n);
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (long ii = 0; ii < nn; ++ii) {
      const auto i = static_cast<std::size_t>(ii);
      ((std::get<I>(acc)[i] = std::get<I>(eqt).init(i)), ...);
    }
    if (ctx.uniform_h > 0.0)
      sweep_pairs<D, Kernel, true>(ctx, ps, eqt, acc, seq);
    else
      sweep_pairs<D, Kernel, false>(ctx, ps, eqt, acc, seq);
#pragma omp for schedule(static)
    for (long ii = 0; ii < nn; ++ii) {
      const auto i = static_cast<std::size_t>(ii);
      (std::get<I>(eqt).finish(std::get<I>(acc)[i], i), ...);
    }
  }
}

}  // namespace detail

// Runs the equations eqs over every pair of the step's grid, timed as phase `name`.
template <int D, class Kernel, class... Eqs>
void sweep(const SweepContext<D>& ctx, const ParticleSet<D>& ps, const char* name, Eqs&... eqs) {
  PhaseClock::Scope timer(ctx.clock, name);
  detail::sweep_group<D, Kernel>(ctx, ps, std::index_sequence_for<Eqs...>{}, eqs...);
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
