#include "flume/neighbors/cell_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <omp.h>

#include <fmt/format.h>

#include "flume/core/error.hpp"

namespace flume {

namespace {
// A grid larger than this means particles are spread absurdly far apart (a particle escaped):
// refuse rather than allocate gigabytes.
constexpr std::size_t kMaxCells = std::size_t{1} << 26;
// Cells are this much wider than the range, so that rounding in (x - origin) / edge can never put
// two points closer than the range into cells two apart (the rounding error of the scaled
// coordinate is a few ulps of at most 2^26, far below 1e-6).
constexpr double kEdgeMargin = 1.0 + 1e-6;
// Fewer points than this are binned by one thread: a team's start and barriers cost more than
// the work (the dam break's ~1900 ghosts at 1e5 particles: 70 us in parallel, flume_bench).
constexpr std::size_t kParallelFrom = 8192;

// Sorts order[b, e) by the x-coordinate of the points, ties by index: an insertion sort, since
// from one step to the next the runs are already nearly sorted.
template <int D>
void sort_run_by_x(std::span<const Vec<D>> x, std::size_t b, std::size_t e,
                   std::vector<std::uint32_t>& order) {
  auto before = [&](std::uint32_t p, std::uint32_t q) {
    return x[p][0] < x[q][0] || (x[p][0] == x[q][0] && p < q);
  };
  for (std::size_t k = b + 1; k < e; ++k) {
    const std::uint32_t v = order[k];
    std::size_t m = k;
    for (; m > b && before(v, order[m - 1]); --m)
      order[m] = order[m - 1];
    order[m] = v;
  }
}

// Sorts each cell's run of `order` (particle k of cell c is order[start[c] - offset + k]) by
// x: cells are contiguous along x, so each row of cells is then sorted by x.
template <int D>
void sort_cells_by_x(std::span<const Vec<D>> x, const std::vector<std::uint32_t>& start,
                     std::uint32_t offset, std::vector<std::uint32_t>& order) {
  const auto cells = static_cast<long>(start.size()) - 1;
#pragma omp parallel for schedule(static) if (x.size() >= kParallelFrom)
  for (long c = 0; c < cells; ++c)
    sort_run_by_x(x, start[static_cast<std::size_t>(c)] - offset,
                  start[static_cast<std::size_t>(c) + 1] - offset, order);
}

// The same for a few points sorted by cell (`cell` of each point, in the order before the
// sort): the runs of one cell found along `order`, in time proportional to the points, not to
// the cells of the grid (the ghosts: 1,900 of them in 14,000 cells at 1e5 particles).
template <int D>
void sort_runs_by_x(std::span<const Vec<D>> x, const std::vector<std::uint32_t>& cell,
                    std::vector<std::uint32_t>& order) {
  const std::size_t n = order.size();
  for (std::size_t b = 0, e = 0; b < n; b = e) {
    const std::uint32_t c = cell[order[b]];
    e = b + 1;
    while (e < n && cell[order[e]] == c)
      ++e;
    sort_run_by_x(x, b, e, order);
  }
}

}  // namespace

template <int D>
std::size_t CellGrid<D>::cell_of(const Vec<D>& p) const {
  std::size_t idx = 0;
  for (int k = D - 1; k >= 0; --k) {
    const double s = (p[k] - origin_[k]) / edge_;
    // Clamped (ghosts far outside): the border cells are never within reach of a real particle.
    const double cs = std::clamp(s, 0.0, static_cast<double>(dims_[k] - 1));
    idx = idx * dims_[k] + static_cast<std::size_t>(cs);
  }
  return idx;
}

template <int D>
void CellGrid<D>::counting_sort_few(const std::vector<std::uint32_t>& cell, std::uint32_t offset,
                                    std::vector<std::uint32_t>& start,
                                    std::vector<std::uint32_t>& order) {
  // The counts live in few_counts_, all zero between calls (only the occupied cells' are
  // touched, and set back to zero at the end), and the occupied cells are bits of a bitmap, so
  // that the running sum visits them in order without a loop over the empty cells: the starts
  // of a run of empty cells are one fill. The dam break's ghosts at 1e5 particles (1,900 in
  // 14,000 cells) took about 35 us a step as the counting sort over every cell.
  const std::size_t n = cell.size();
  const std::size_t cells = cell_count_;
  if (few_counts_.size() < cells) few_counts_.resize(cells);  // new counts are zero
  occupied_.assign((cells + 63) / 64, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t c = cell[i];
    ++few_counts_[c];
    occupied_[c / 64] |= std::uint64_t{1} << (c % 64);
  }
  // Each occupied cell's start, in cell order; cells [next, c] start where c does.
  std::uint32_t run = offset;
  std::size_t next = 0;
  auto each_occupied = [&](auto&& f) {
    for (std::size_t w = 0; w < occupied_.size(); ++w)
      for (std::uint64_t bits = occupied_[w]; bits != 0; bits &= bits - 1)
        f(w * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
  };
  each_occupied([&](std::size_t c) {
    std::fill(start.begin() + static_cast<std::ptrdiff_t>(next),
              start.begin() + static_cast<std::ptrdiff_t>(c) + 1, run);
    const std::uint32_t here = few_counts_[c];
    few_counts_[c] = run - offset;  // now where the cell's next particle goes in `order`
    run += here;
    next = c + 1;
  });
  std::fill(start.begin() + static_cast<std::ptrdiff_t>(next), start.end(), run);
  for (std::size_t i = 0; i < n; ++i)
    order[few_counts_[cell[i]]++] = static_cast<std::uint32_t>(i);
  each_occupied([&](std::size_t c) { few_counts_[c] = 0; });
}

template <int D>
void CellGrid<D>::counting_sort(const std::vector<std::uint32_t>& cell, std::uint32_t offset,
                                std::vector<std::uint32_t>& start,
                                std::vector<std::uint32_t>& order) {
  // (Fewer points than kParallelFrom: counting_sort_few, by one thread.)
  // Stable and in parallel: thread t counts the particles of its contiguous chunk per cell,
  // the offsets run over (cell, thread), and each thread places its chunk in index order. A
  // cell then holds its particles in index order for any number of threads, the order of the
  // serial counting sort. Every step of it is shared among the threads: each zeroes its own
  // counts, and the running sum over the cells is taken in two passes over each thread's range
  // of cells (its total, then its offsets from the totals before it). Done by one thread
  // (`omp single`), the zeroing and the running sum over the dam break's 14,000 cells at 1e5
  // particles kept the other thread waiting: the sort took 120-130 us a step, now 95-105.
  const std::size_t n = cell.size();
  const std::size_t cells = cell_count_;
  start.resize(cells + 1);
  order.resize(n);
  if (n < kParallelFrom) {
    counting_sort_few(cell, offset, start, order);
    return;
  }
  const auto most = static_cast<std::size_t>(omp_get_max_threads());
  if (thread_counts_.size() < most * cells) thread_counts_.resize(most * cells);
  cell_totals_.resize(most);
#pragma omp parallel
  {
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    std::uint32_t* count = thread_counts_.data() + t * cells;
    std::fill(count, count + cells, 0U);
    // The chunk of thread t, as schedule(static) would cut it.
    const std::size_t lo = n * t / threads, hi = n * (t + 1) / threads;
    for (std::size_t i = lo; i < hi; ++i)
      ++count[cell[i]];
#pragma omp barrier
    const std::size_t c_lo = cells * t / threads, c_hi = cells * (t + 1) / threads;
    std::uint32_t total = 0;
    for (std::size_t u = 0; u < threads; ++u) {
      const std::uint32_t* row = thread_counts_.data() + u * cells;
      for (std::size_t c = c_lo; c < c_hi; ++c)
        total += row[c];
    }
    cell_totals_[t] = total;
#pragma omp barrier
    std::uint32_t run = offset;
    for (std::size_t u = 0; u < t; ++u)
      run += cell_totals_[u];
    for (std::size_t c = c_lo; c < c_hi; ++c) {
      start[c] = run;
      for (std::size_t u = 0; u < threads; ++u) {
        std::uint32_t& k = thread_counts_[u * cells + c];
        const std::uint32_t here = k;
        k = run - offset;
        run += here;
      }
    }
#pragma omp barrier
    for (std::size_t i = lo; i < hi; ++i)
      order[count[cell[i]]++] = static_cast<std::uint32_t>(i);
  }
  start[cells] = offset + static_cast<std::uint32_t>(n);
}

template <int D>
const std::vector<std::uint32_t>& CellGrid<D>::sort_real(std::span<const Vec<D>> x, double range) {
  Vec<D> lo, hi;
  double l[D], h[D];  // plain arrays: what OpenMP reduces as array sections
  for (int k = 0; k < D; ++k) {
    l[k] = std::numeric_limits<double>::max();
    h[k] = std::numeric_limits<double>::lowest();
  }
  const auto n = static_cast<long>(x.size());
  bool finite = true;
  // Every axis in one pass (a pass per axis was a team start and a barrier more each).
#pragma omp parallel for schedule(static) reduction(min : l[:D]) reduction(max : h[:D]) \
    reduction(&& : finite)
  for (long i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) {
      const double v = x[static_cast<std::size_t>(i)][k];
      finite = finite && std::isfinite(v);
      l[k] = std::min(l[k], v);
      h[k] = std::max(h[k], v);
    }
  }
  if (!finite) throw SimulationError("cell grid: non-finite particle position");
  for (int k = 0; k < D; ++k) {
    lo[k] = x.empty() ? 0.0 : l[k];
    hi[k] = x.empty() ? 0.0 : h[k];
  }
  return sort_real(x, range, lo, hi);
}

template <int D>
const std::vector<std::uint32_t>& CellGrid<D>::sort_real(std::span<const Vec<D>> x, double range,
                                                         const Vec<D>& lo, const Vec<D>& hi) {
  if (!(range > 0.0)) throw SimulationError("cell grid: range must be positive");
  if (x.size() >= std::numeric_limits<std::uint32_t>::max() / 2)
    throw SimulationError("cell grid: too many particles for 32-bit indices");
  range_ = range;
  edge_ = range * kEdgeMargin;
  n_real_ = x.size();
  const auto n = static_cast<long>(x.size());
  cell_count_ = 1;
  for (int k = 0; k < D; ++k) {
    const double extent = (hi[k] - lo[k]) / edge_;
    if (extent > static_cast<double>(kMaxCells))
      throw SimulationError(
          fmt::format("cell grid: particles spread over {:.3g} interaction ranges along axis {}; "
                      "a particle has escaped",
                      extent, k));
    origin_[k] = lo[k] - kPad * edge_;
    dims_[k] = static_cast<std::size_t>(extent) + 1 + 2 * kPad;
    strides_[k] = cell_count_;
    cell_count_ *= dims_[k];
    if (cell_count_ > kMaxCells)
      throw SimulationError("cell grid: too many cells; particles are spread too far apart");
  }

  real_cell_.resize(x.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
    real_cell_[static_cast<std::size_t>(i)] =
        static_cast<std::uint32_t>(cell_of(x[static_cast<std::size_t>(i)]));
  counting_sort(real_cell_, 0, real_start_, order_);
  sort_cells_by_x(x, real_start_, 0, order_);
  // The cells in the sorted order (a counting sort leaves them ascending).
  const auto cells = static_cast<long>(cell_count_);
#pragma omp parallel for schedule(static)
  for (long cc = 0; cc < cells; ++cc) {
    const auto c = static_cast<std::size_t>(cc);
    for (std::uint32_t k = real_start_[c]; k < real_start_[c + 1]; ++k)
      real_cell_[k] = static_cast<std::uint32_t>(c);
  }
  return order_;
}

template <int D>
const std::vector<std::uint32_t>& CellGrid<D>::sort_ghosts(std::span<const Vec<D>> ghost_x) {
  ghost_cell_.resize(ghost_x.size());
  const auto n = static_cast<long>(ghost_x.size());
#pragma omp parallel for schedule(static) if (ghost_x.size() >= kParallelFrom)
  for (long g = 0; g < n; ++g)
    ghost_cell_[static_cast<std::size_t>(g)] =
        static_cast<std::uint32_t>(cell_of(ghost_x[static_cast<std::size_t>(g)]));
  counting_sort(ghost_cell_, static_cast<std::uint32_t>(n_real_), ghost_start_, order_);
  if (ghost_x.size() >= kParallelFrom)
    sort_cells_by_x(ghost_x, ghost_start_, static_cast<std::uint32_t>(n_real_), order_);
  else
    sort_runs_by_x(ghost_x, ghost_cell_, order_);
  return order_;
}

template <int D>
void CellGrid<D>::runs_outside(const Vec<D>& lo, const Vec<D>& hi,
                               std::vector<std::pair<std::uint32_t, std::uint32_t>>& runs) const {
  // Along axis k, the layers l <= first[k] reach below lo[k] and the layers l >= last[k] above
  // hi[k] (in cell units, widened by two layers; infinite bounds give infinite limits).
  std::array<double, D> first, last;
  for (int k = 0; k < D; ++k) {
    first[k] = (lo[k] - origin_[k]) / edge_ + 2.0;
    last[k] = (hi[k] - origin_[k]) / edge_ - 2.0;
  }
  auto add = [&](std::size_t c_begin, std::size_t c_end) {  // the cells [c_begin, c_end)
    const std::uint32_t b = real_start_[c_begin], e = real_start_[c_end];
    if (b == e) return;
    if (!runs.empty() && runs.back().second == b)
      runs.back().second = e;
    else
      runs.emplace_back(b, e);
  };
  const std::size_t nx = dims_[0];
  const std::size_t rows = cell_count_ / nx;
  for (std::size_t r = 0; r < rows; ++r) {
    // The row's layer along each axis but x (the row index r in the strides of axes 1..D-1).
    bool whole = false;
    std::size_t rest = r;
    for (int k = 1; k < D; ++k) {
      const auto l = static_cast<double>(rest % dims_[k]);
      rest /= dims_[k];
      whole = whole || l <= first[k] || l >= last[k];
    }
    const std::size_t c0 = r * nx;
    if (whole) {
      add(c0, c0 + nx);
      continue;
    }
    // The layers along x below and above: [0, a) and [b, nx).
    const double dnx = static_cast<double>(nx);
    const auto a = static_cast<std::size_t>(std::clamp(std::floor(first[0]) + 1.0, 0.0, dnx));
    const auto b = static_cast<std::size_t>(std::clamp(std::ceil(last[0]), 0.0, dnx));
    if (a >= b) {
      add(c0, c0 + nx);
    } else {
      add(c0, c0 + a);
      add(c0 + b, c0 + nx);
    }
  }
}

template <int D>
std::size_t CellGrid<D>::bytes() const {
  return sizeof(std::uint32_t) *
             (real_start_.capacity() + ghost_start_.capacity() + real_cell_.capacity() +
              ghost_cell_.capacity() + order_.capacity() + thread_counts_.capacity() +
              cell_totals_.capacity() + few_counts_.capacity()) +
         sizeof(std::uint64_t) * occupied_.capacity();
}

template class CellGrid<2>;
template class CellGrid<3>;

}  // namespace flume
