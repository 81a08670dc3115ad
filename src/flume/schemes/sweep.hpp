// The loop driver: one fused sweep over every interacting pair of particles, running a group of
// equations (PySPH's Group). The driver owns loops, threads, pair symmetry and the geometry; an
// equation has the fixed shape (docs/adding_an_equation.md)
//   using Acc = ...;                    what one particle accumulates (double, Vec, Mat, struct)
//   Acc init(i);                        its starting value
//   void pair(Acc& ai, Acc& aj, i, j, const Pair<D>& g);   both particles' shares of pair (i, j)
//   void finish(Acc& a, i);             turns the sum into particle i's fields
// and, optionally, per-particle factors computed once before the pairs (own.hpp); it knows
// nothing of loops or threads.
// Each pair of real particles is visited once (a half stencil of cells: the rest of i's own cell
// and the cell after it along x, then the rows of cells ahead; each row of cells is sorted by x,
// so its run is cut to the particles within one range of x_i), and the equation gives i and j
// their shares. A pair with a ghost j is visited from the real side only, with a scratch aj that
// is thrown away (ghosts are copies refreshed from their sources). The self pair (i, i) is
// visited once with r = 0, W = W(0), grad W = 0 and a scratch aj.
// Vectorisation: the candidates of each run of cells are evaluated in blocks of kLanes without a
// branch (pair_block), the equations inlined; candidates beyond the support give exact zeros.
// Threads: the cell layers along the slowest axis are cut into slabs; a pair touches the
// accumulators of its own layer and the next only, so the even slabs run in parallel, and an
// odd slab runs once both its even neighbours are done (sweep_pairs). Every accumulator then
// receives its terms in an order fixed by the positions alone: results are bit-identical for
// any thread count.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include <omp.h>

#include "flume/core/particle_set.hpp"
#include "flume/equations/own.hpp"
#include "flume/equations/pair.hpp"
#include "flume/neighbors/cell_grid.hpp"
#include "flume/schemes/particle_passes.hpp"
#include "flume/schemes/slab_schedule.hpp"
#include "flume/schemes/sweep_stores.hpp"
#include "flume/schemes/sweep_workspace.hpp"
#include "flume/sim/phase_clock.hpp"

// flatten inlines the equations into the vectorised pair loop. The sanitizer build (a test build,
// not a fast one) goes without: with the instrumentation, flattening multiplies its compile time.
#if defined(__SANITIZE_ADDRESS__)
#define FLUME_FLATTEN
#else
#define FLUME_FLATTEN [[gnu::flatten]]
#endif

namespace flume {

namespace detail {
// Whether a step whose particles share one h takes the pair loop specialised for it (h and the
// cut constants hoisted). The sanitizer build sweeps every step through the general loop: the
// two differ only in where h comes from (the general one also reads h_j, a superset of the
// fast loop's memory accesses: the same windows, indices and stores), and compiling one loop
// instead of two halves each kernel's scheme unit there (CI's longest compile jobs).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUniformHPath = false;
#else
inline constexpr bool kUniformHPath = true;
#endif
}  // namespace detail

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

// Pair (i, j) of a block: i's share goes to partial sum k (Lanes) or to shares.block[k], j's
// to its accumulator (Real) or nowhere (a ghost j, whose accumulator is not kept).
template <bool Real, bool Lanes, class Eq, class Acc, class O, int D>
inline void pair_share(const Eq& eq, const AccStore<Acc>& acc, const OwnStore<O>& own,
                       Shares<Acc>& __restrict shares, std::size_t i, std::size_t j, std::size_t k,
                       const Pair<D>& g) {
  Acc a_i{}, a_j{};
  pair_of(eq, a_i, a_j, own.get(i), own.get(j), i, j, g);
  if constexpr (Real) acc.add(j, a_j);
  if constexpr (Lanes)
    shares.add_lane(k, a_i);
  else
    shares.put(k, a_i);
}

// Pairs (i, j) for j in [lo, ce), evaluated over the window [cb, ce) (cb <= lo, at most kChunk
// candidates). The loop has no branch: a candidate beyond the support, or before lo, gets
// in = 0, w = 0 and grad W = 0 (every term of an SPH sum carries W or grad W, so its shares are
// exactly zero), and the compiler vectorises the loop over j. flatten inlines the equations.
// When the window is a whole number of kLanes (Lanes), it is walked in groups of kLanes, lane l
// of each group adding i's share to partial sum l directly; otherwise the shares go through
// shares.block and are folded after the loop. (Its two wrappers below: pair_block, flattened,
// and pair_block_rare.)
template <int D, class Kernel, bool UniformH, bool Real, bool Lanes, class EqTuple, class AccTuple,
          class OwnTuple, class ShareTuple, std::size_t... I>
inline void pair_block_body(const ParticleSet<D>& ps, double h0, EqTuple& eqs, AccTuple& acc,
                            const OwnTuple& own, ShareTuple& shares, std::size_t i, std::size_t cb,
                            std::size_t lo, std::size_t ce, std::index_sequence<I...>) {
  const Vec<D>* x = ps.x.data();
  const double* hs = ps.h.data();
  const Vec<D> xi = x[i];
  const double hi = hs[i];
  const double cut0 = Kernel::support * h0;
  const double cut2_0 = cut0 * cut0;
  auto pair_at = [&](std::size_t j, std::size_t k) {
    Pair<D> g;
    g.xij = xi - x[j];
    const double r2 = norm2(g.xij);
    double h = h0, cut2 = cut2_0;
    if constexpr (!UniformH) {
      h = 0.5 * (hi + hs[j]);
      cut2 = Kernel::support * h * Kernel::support * h;
    }
    const bool in = r2 < cut2 && j >= lo;
    g.r = std::sqrt(r2);
    g.h = h;
    // Evaluated in every lane, then masked (a masked evaluation would redo 1/h in the loop);
    // the mask is the kernel's cut (Kernel::inside has none).
    double w, factor;
    Kernel::inside(g.r, h, w, factor);
    g.w = in ? w : 0.0;
    g.gradw = g.xij * (in ? factor : 0.0);
    g.in = in ? 1.0 : 0.0;
    (pair_share<Real, Lanes>(std::get<I>(eqs), std::get<I>(acc), std::get<I>(own),
                             std::get<I>(shares), i, j, k, g),
     ...);
  };
  if constexpr (Lanes) {
    for (std::size_t gb = cb; gb < ce; gb += kLanes) {
      // ivdep: the lanes touch different j and different partial sums.
#pragma GCC ivdep
      for (std::size_t l = 0; l < kLanes; ++l)
        pair_at(gb + l, l);
    }
  } else {
#pragma GCC ivdep
    for (std::size_t j = cb; j < ce; ++j)
      pair_at(j, j - cb);
    (std::get<I>(shares).fold(ce - cb), ...);
  }
}

// A window of a whole number of kLanes, the equations flattened into the vectorised loop.
template <int D, class Kernel, bool UniformH, bool Real, class EqTuple, class AccTuple,
          class OwnTuple, class ShareTuple, std::size_t... I>
FLUME_FLATTEN void pair_block(const ParticleSet<D>& ps, double h0, EqTuple& eqs, AccTuple& acc,
                              const OwnTuple& own, ShareTuple& shares, std::size_t i,
                              std::size_t cb, std::size_t lo, std::size_t ce,
                              std::index_sequence<I...> seq) {
  pair_block_body<D, Kernel, UniformH, Real, true>(ps, h0, eqs, acc, own, shares, i, cb, lo, ce,
                                                   seq);
}

// A window that cannot be widened to a whole number of kLanes within the particles this thread
// may touch (a few windows at the start of a slab, and tiny sets): rare, so out of line and not
// flattened. Compiled as pair_block is, flattened into the slab, it took a quarter of each
// kernel's scheme unit (the Wendland unit 210 s with it, 156 s without: two compiles at once).
template <int D, class Kernel, bool UniformH, bool Real, class EqTuple, class AccTuple,
          class OwnTuple, class ShareTuple, std::size_t... I>
[[gnu::noinline]] void pair_block_rare(const ParticleSet<D>& ps, double h0, EqTuple& eqs,
                                       AccTuple& acc, const OwnTuple& own, ShareTuple& shares,
                                       std::size_t i, std::size_t cb, std::size_t ce,
                                       std::index_sequence<I...> seq) {
  pair_block_body<D, Kernel, UniformH, Real, false>(ps, h0, eqs, acc, own, shares, i, cb, cb, ce,
                                                    seq);
}

// pair_block kept out of the slab's loop. The slab (flattened) inlines pair_block when the
// group accumulates scalars (density, continuity: 10-16 % faster, the block's set-up hoisted
// out of the particle loop) and calls it through this for larger accumulators: inlined, the
// momentum sweep ran 3 % slower and CSPH's correction sweep (two 2 x 2 matrices) 2.7 x slower.
template <int D, class Kernel, bool UniformH, bool Real, class EqTuple, class AccTuple,
          class OwnTuple, class ShareTuple, std::size_t... I>
[[gnu::noinline]] void pair_block_call(const ParticleSet<D>& ps, double h0, EqTuple& eqs,
                                       AccTuple& acc, const OwnTuple& own, ShareTuple& shares,
                                       std::size_t i, std::size_t cb, std::size_t lo,
                                       std::size_t ce, std::index_sequence<I...> seq) {
  pair_block<D, Kernel, UniformH, Real>(ps, h0, eqs, acc, own, shares, i, cb, lo, ce, seq);
}

// The pairs of the particles i of the cells [c_begin, c_end) (one slab), as sweep_pairs says.
// One function, flattened, for the whole slab: the block loops, the equations and the window
// ends are inlined together, so what does not change from one particle to the next (constants,
// field pointers, the equations' parameters) is set up once per slab, not once per run.
template <int D, class Kernel, bool UniformH, class EqTuple, class AccTuple, class OwnTuple,
          class ShareTuple, std::size_t... I>
FLUME_FLATTEN void slab_pairs(const CellGrid<D>& grid, const ParticleSet<D>& ps, double h0,
                              EqTuple& eqs, AccTuple& acc, const OwnTuple& own, ShareTuple& shares,
                              std::size_t c_begin, std::size_t c_end,
                              std::index_sequence<I...> seq) {
  using Accs = std::tuple<typename std::tuple_element_t<I, AccTuple>::Value...>;
  const RowOffsets<D> rows(grid.strides());
  const double w0 = UniformH ? Kernel::w(0.0, h0) : 0.0;  // W(0) of the self pair
  const auto* hs = ps.h.data();
  const Vec<D>* x = ps.x.data();
  const double range = grid.range();
  const std::size_t row_cells = grid.dims()[0];
  constexpr bool kInlineBlocks = ((AccStore<std::tuple_element_t<I, Accs>>::kDoubles == 1) && ...);

  // Pairs (i, j), j in [jb, je), in blocks of kChunk. A block of n candidates that is not a
  // whole number of kLanes is widened backwards to one (its first lanes masked), so the
  // vectorised loop never ends in a scalar remainder. The widened window may reach particles of
  // other cells: their shares are exact zeros, but a real j's accumulator is still written, so
  // the window must stay within [owned, je), the particles whose accumulators only this thread
  // touches in this phase (its slab's layers and the next); ghosts are not written at all.
  // A block that cannot be widened within them goes to pair_block_rare.
  const std::size_t owned = grid.real_begin(c_begin);
  auto run = [&](std::size_t i, std::size_t jb, std::size_t je, auto real) {
    constexpr bool kReal = decltype(real)::value;
    const std::size_t floor = kReal ? owned : 0;
    for (std::size_t cb = jb; cb < je; cb += kChunk) {
      const std::size_t ce = std::min(je, cb + kChunk);
      const std::size_t n = ce - cb;
      const std::size_t widened = (n + kLanes - 1) / kLanes * kLanes;
      if (ce < floor + widened)
        pair_block_rare<D, Kernel, UniformH, kReal>(ps, h0, eqs, acc, own, shares, i, cb, ce, seq);
      else if constexpr (kInlineBlocks)
        pair_block<D, Kernel, UniformH, kReal>(ps, h0, eqs, acc, own, shares, i, ce - widened, cb,
                                               ce, seq);
      else
        pair_block_call<D, Kernel, UniformH, kReal>(ps, h0, eqs, acc, own, shares, i, ce - widened,
                                                    cb, ce, seq);
    }
  };

  // The ends of the windows, [lo, hi) of each run: along a row of cells the particles are
  // sorted by x, and so are the i taken in turn, so the ends only move forward within a row;
  // they restart with each row.
  std::size_t own_hi = 0;
  std::array<std::size_t, RowOffsets<D>::kAhead> ahead_lo{}, ahead_hi{};
  std::array<std::size_t, RowOffsets<D>::kRows> ghost_lo{}, ghost_hi{};
  for (std::size_t c = c_begin; c < c_end; ++c) {
    if (c == c_begin || (D > 1 && c % row_cells == 0)) {
      own_hi = 0;
      ahead_lo.fill(0);
      ahead_hi.fill(0);
      ghost_lo.fill(0);
      ghost_hi.fill(0);
    }
    const std::size_t b = grid.real_begin(c), e = grid.real_begin(c + 1);
    if (b == e) continue;
    // The runs of ghosts around this cell (most cells have none within reach).
    std::array<std::size_t, RowOffsets<D>::kRows> ghost_b{}, ghost_e{};
    bool any_ghost = false;
    for (std::size_t k = 0; k < RowOffsets<D>::kRows; ++k) {
      const std::size_t cr = c + static_cast<std::size_t>(rows.all[k]);
      ghost_b[k] = grid.ghost_begin(cr - 1);
      ghost_e[k] = grid.ghost_begin(cr + 2);
      any_ghost = any_ghost || ghost_b[k] != ghost_e[k];
    }
    for (std::size_t i = b; i < e; ++i) {
      Accs ai{std::get<I>(acc).get(i)...};
      (std::get<I>(shares).clear(), ...);
      {  // the self pair (not for equations that carry grad W only: it adds zeros there)
        Accs scratch{};
        Pair<D> g0;
        g0.h = hs[i];
        g0.w = UniformH ? w0 : Kernel::w(0.0, hs[i]);
        auto self = [&](const auto& eq, auto& a_i, auto& a_scratch, const auto& store) {
          if constexpr (!gradient_only<std::remove_cvref_t<decltype(eq)>>())
            pair_of(eq, a_i, a_scratch, store.get(i), store.get(i), i, i, g0);
        };
        (self(std::get<I>(eqs), std::get<I>(ai), std::get<I>(scratch), std::get<I>(own)), ...);
      }
      // Each run of three cells along x is sorted by x (CellGrid): only its particles with x
      // within one range of x_i can interact with i.
      const double x_lo = x[i][0] - range, x_hi = x[i][0] + range;
      auto slide = [&](std::size_t& lo, std::size_t& hi, std::size_t jb, std::size_t je) {
        lo = std::max(lo, jb);
        while (lo < je && x[lo][0] < x_lo)
          ++lo;
        hi = std::max(hi, lo);
        while (hi < je && x[hi][0] <= x_hi)
          ++hi;
      };
      // The rest of the own cell and the cell after it along x: one run.
      std::size_t own_lo = i + 1;
      slide(own_lo, own_hi, i + 1, grid.real_begin(c + 2));
      run(i, i + 1, own_hi, std::true_type{});
      for (int r = 0; r < RowOffsets<D>::kAhead; ++r) {
        const auto k = static_cast<std::size_t>(r);
        const std::size_t cr = c + static_cast<std::size_t>(rows.all[k]);
        slide(ahead_lo[k], ahead_hi[k], grid.real_begin(cr - 1), grid.real_begin(cr + 2));
        run(i, ahead_lo[k], ahead_hi[k], std::true_type{});
      }
      if (any_ghost) {
        for (std::size_t k = 0; k < RowOffsets<D>::kRows; ++k) {
          slide(ghost_lo[k], ghost_hi[k], ghost_b[k], ghost_e[k]);
          run(i, ghost_lo[k], ghost_hi[k], std::false_type{});
        }
      }
      // i's accumulator: what earlier particles gave it as their j, the self pair, then the
      // partial sums.
      (std::get<I>(acc).set(i, std::get<I>(shares).total(std::get<I>(ai))), ...);
    }
  }
}

// Scheduling. Slab s writes the accumulators of its own layers and of the next slab's first
// layer, so neighbouring slabs cannot run at the same time; and for results that do not depend
// on the thread count every accumulator must receive its terms in one order: the even slabs'
// before the odd slabs' (the order of a single thread doing all even slabs, then all odd ones).
// Each thread takes the slabs of its share of the particles (slabs_of_thread): first its even
// slabs upwards, then its odd slabs downwards, each odd slab once both its even neighbours are
// done. A thread that has finished its share then takes the odd slabs that another has not
// reached, from the bottom of that share up (each odd slab is claimed once: flags), so that
// the threads end together when one share costs more (the lower half of the bench's dam break
// about 10 %, flume_bench) or one core is slower. The even slabs never wait, so no thread
// waits for ever.
template <int D, class Kernel, bool UniformH, class EqTuple, class AccTuple, class OwnTuple,
          std::size_t... I>
void sweep_pairs(const SweepContext<D>& ctx, const ParticleSet<D>& ps, EqTuple& eqs, AccTuple& acc,
                 const OwnTuple& own, SlabFlag* flags, std::index_sequence<I...> seq) {
  using Accs = std::tuple<typename std::tuple_element_t<I, AccTuple>::Value...>;
  const CellGrid<D>& grid = ctx.grid;
  const std::size_t layer = grid.strides()[D - 1];
  const auto layers = static_cast<std::size_t>(grid.dims()[D - 1]);
  const long slabs = slab_count(grid);
  auto first_cell = [&](long s) { return static_cast<std::size_t>(s) * kSlabLayers * layer; };
  auto done = [&](long s) { return std::atomic_ref<int>(flags[2 * s].v); };
  // claim(s) is true for the one thread that takes odd slab s.
  auto claim = [&](long s) {
    return std::atomic_ref<int>(flags[2 * s + 1].v).exchange(1, std::memory_order_relaxed) == 0;
  };
  const auto threads = static_cast<std::size_t>(omp_get_num_threads());
  const auto me = static_cast<std::size_t>(omp_get_thread_num());
  auto share = [&](std::size_t t) {
    return slabs_of_thread(slabs, ps.n_real, t, threads, [&](long s) {
      return static_cast<std::size_t>(grid.real_begin(first_cell(s)));
    });
  };
  const auto [first, last] = share(me);
  // Per thread: i's shares of the pairs of a block, and their partial sums.
  std::tuple<Shares<std::tuple_element_t<I, Accs>>...> shares;
  auto run = [&](long s) {
    const std::size_t c_end =
        std::min(static_cast<std::size_t>(s + 1) * kSlabLayers, layers) * layer;
    slab_pairs<D, Kernel, UniformH>(grid, ps, ctx.uniform_h, eqs, acc, own, shares, first_cell(s),
                                    c_end, seq);
  };
  auto run_odd = [&](long s) {
    wait_done(done(s - 1));
    if (s + 1 < slabs) wait_done(done(s + 1));
    run(s);
  };
  for (long s = first + first % 2; s < last; s += 2) {
    run(s);
    mark_done(done(s));
  }
  for (long s = last - 1; s >= first; --s)
    if (s % 2 == 1 && claim(s)) run_odd(s);
  // Then the odd slabs that the other threads have not reached, from the bottom of each share.
  for (std::size_t k = 1; k < threads; ++k) {
    const auto [vf, vl] = share((me + k) % threads);
    for (long s = vf + 1 - vf % 2; s < vl; s += 2)
      if (claim(s)) run_odd(s);
  }
#pragma omp barrier
}

// The store `slot` of eq's per-particle factors, for n particles (empty when it has none).
template <class Eq>
OwnStore<OwnOf<Eq>> own_store(SweepWorkspace& work, const Eq&, std::size_t slot, std::size_t n) {
  using Store = OwnStore<OwnOf<Eq>>;
  if constexpr (Store::kDoubles == 0)
    return {};
  else
    return {work.template buffer<typename Store::Component>(slot, Store::kDoubles * n).data(), n};
}

// The accumulator store `slot` of type Acc for n particles.
template <int D, class Acc>
AccStore<Acc> acc_store(SweepWorkspace& work, std::size_t slot, std::size_t n) {
  using Element = AccBuffer<AccStore<Acc>::kDoubles, D>;
  static_assert(sizeof(Element) == AccStore<Acc>::kDoubles * sizeof(double));
  auto& buffer = work.template buffer<Element>(kFirstAccSlot + slot, n);
  // The elements are doubles side by side (double, Vec<D> or std::array of doubles).
  return {reinterpret_cast<double*>(buffer.data()), n};
}

// Runs the group; then(i) follows the equations' finish of each real particle i. Or, when
// then takes a block of particles [b, e), then(b, e) follows the finish of each block, and
// when it returns a number the group returns the least of those numbers (else +infinity).
template <int D, class Kernel, class Then, class... Eqs, std::size_t... I>
double sweep_group(const SweepContext<D>& ctx, const ParticleSet<D>& ps, const Then& then,
                   std::index_sequence<I...> seq, Eqs&... eqs) {
  const std::size_t n = ps.n_real;
  std::tuple<AccStore<typename Eqs::Acc>...> acc{
      acc_store<D, typename Eqs::Acc>(ctx.work, I, n)...};
  std::tuple<Eqs&...> eqt{eqs...};
  // The equations' per-particle factors, for real and ghost particles (empty stores: none).
  std::tuple<OwnStore<OwnOf<Eqs>>...> own{own_store(ctx.work, eqs, I, ps.size())...};
  const auto nn = static_cast<long>(n);
  const auto n_all = static_cast<long>(ps.size());
  double least = std::numeric_limits<double>::infinity();
  auto& flags =
      ctx.work.template buffer<SlabFlag>(0, 2 * static_cast<std::size_t>(slab_count(ctx.grid)));
  std::fill(flags.begin(), flags.end(), SlabFlag{0});
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (long bb = 0; bb < n_all; ++bb) {
      const auto b = static_cast<std::size_t>(bb);
      auto fill = [&](const auto& eq, const auto& store) {
        if constexpr (HasOwn<std::remove_cvref_t<decltype(eq)>>) store.set(b, eq.own(b));
      };
      (fill(std::get<I>(eqt), std::get<I>(own)), ...);
    }
#pragma omp for schedule(static)
    for (long ii = 0; ii < nn; ++ii) {
      const auto i = static_cast<std::size_t>(ii);
      (std::get<I>(acc).set(i, std::get<I>(eqt).init(i)), ...);
    }
    if (kUniformHPath && ctx.uniform_h > 0.0)
      sweep_pairs<D, Kernel, kUniformHPath>(ctx, ps, eqt, acc, own, flags.data(), seq);
    else
      sweep_pairs<D, Kernel, false>(ctx, ps, eqt, acc, own, flags.data(), seq);
    auto finish = [&](std::size_t i) {
      auto one = [&](const auto& eq, const auto& store) {
        auto a = store.get(i);
        eq.finish(a, i);
      };
      (one(std::get<I>(eqt), std::get<I>(acc)), ...);
    };
    if constexpr (std::is_invocable_v<const Then&, std::size_t>) {
#pragma omp for simd schedule(static)
      for (long ii = 0; ii < nn; ++ii) {
        finish(static_cast<std::size_t>(ii));
        then(static_cast<std::size_t>(ii));
      }
    } else {
      // In blocks: the finish of a block, then then(b, e) over it (the time step's square roots
      // and divisions, in a loop of its own that the compiler vectorises; in one loop with the
      // finish they did not vectorise), the block's fields still in cache. A minimum is exact:
      // the same for any thread count and any order.
      constexpr auto kBlock = static_cast<long>(kParticleBlock);
      const long blocks = (nn + kBlock - 1) / kBlock;
#pragma omp for schedule(static) reduction(min : least)
      for (long bb = 0; bb < blocks; ++bb) {
        const long b = bb * kBlock, e = std::min(nn, b + kBlock);
        for (long ii = b; ii < e; ++ii)
          finish(static_cast<std::size_t>(ii));
        const auto bs = static_cast<std::size_t>(b), es = static_cast<std::size_t>(e);
        if constexpr (std::is_void_v<std::invoke_result_t<const Then&, std::size_t, std::size_t>>)
          then(bs, es);
        else
          least = std::min(least, static_cast<double>(then(bs, es)));
      }
    }
  }
  return least;
}

}  // namespace detail

// Runs the equations eqs over every pair of the step's grid, timed as phase `name`.
template <int D, class Kernel, class... Eqs>
void sweep(const SweepContext<D>& ctx, const ParticleSet<D>& ps, const char* name, Eqs&... eqs) {
  PhaseClock::Scope timer(ctx.clock, name);
  detail::sweep_group<D, Kernel>(
      ctx, ps, [](std::size_t) {}, std::index_sequence_for<Eqs...>{}, eqs...);
}

// As sweep, then then(i) for each real particle i in the same pass as the equations' finish:
// a per-particle step that needs the sweep's result (the equation of state after the summation
// density) without a pass of its own over the particles (each such pass reads and writes
// memory: at 1e5 particles the state does not stay in cache between passes). Or then(b, e)
// after the finish of each block of particles, as sweep_least: a loop of its own that the
// compiler vectorises.
template <int D, class Kernel, class Then, class... Eqs>
void sweep_then(const SweepContext<D>& ctx, const ParticleSet<D>& ps, const char* name,
                const Then& then, Eqs&... eqs) {
  PhaseClock::Scope timer(ctx.clock, name);
  detail::sweep_group<D, Kernel>(ctx, ps, then, std::index_sequence_for<Eqs...>{}, eqs...);
}

// As sweep_then, where then(b, e) returns a number for the real particles [b, e) after their
// finish (the least time-step limit of a block, after the force sweep): returns the least of
// them, taken in the same pass.
template <int D, class Kernel, class Then, class... Eqs>
double sweep_least(const SweepContext<D>& ctx, const ParticleSet<D>& ps, const char* name,
                   const Then& then, Eqs&... eqs) {
  PhaseClock::Scope timer(ctx.clock, name);
  return detail::sweep_group<D, Kernel>(ctx, ps, then, std::index_sequence_for<Eqs...>{}, eqs...);
}

}  // namespace flume
