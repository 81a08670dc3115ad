#include "flume/neighbors/cell_grid.hpp"

#include <algorithm>
#include <cmath>
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

// Sorts each cell's run of `order` (particle k of cell c is order[start[c] - offset + k]) by the
// x-coordinate, ties by index: cells are contiguous along x, so each row of cells is then sorted
// by x. An insertion sort: from one step to the next the runs are already nearly sorted.
template <int D>
void sort_cells_by_x(std::span<const Vec<D>> x, const std::vector<std::uint32_t>& start,
                     std::uint32_t offset, std::vector<std::uint32_t>& order) {
  const auto cells = static_cast<long>(start.size()) - 1;
  auto before = [&](std::uint32_t a, std::uint32_t b) {
    return x[a][0] < x[b][0] || (x[a][0] == x[b][0] && a < b);
  };
#pragma omp parallel for schedule(static) if (x.size() >= kParallelFrom)
  for (long c = 0; c < cells; ++c) {
    const std::size_t b = start[static_cast<std::size_t>(c)] - offset;
    const std::size_t e = start[static_cast<std::size_t>(c) + 1] - offset;
    for (std::size_t k = b + 1; k < e; ++k) {
      const std::uint32_t v = order[k];
      std::size_t m = k;
      for (; m > b && before(v, order[m - 1]); --m)
        order[m] = order[m - 1];
      order[m] = v;
    }
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
void CellGrid<D>::counting_sort(const std::vector<std::uint32_t>& cell, std::uint32_t offset,
                                std::vector<std::uint32_t>& start,
                                std::vector<std::uint32_t>& order) {
  // Stable and in parallel: thread t counts the particles of its contiguous chunk per cell,
  // the offsets run over (cell, thread), and each thread places its chunk in index order. A
  // cell then holds its particles in index order for any number of threads, the order of the
  // serial counting sort.
  const std::size_t n = cell.size();
  const std::size_t cells = cell_count_;
  start.resize(cells + 1);
  order.resize(n);
#pragma omp parallel if (n >= kParallelFrom)
  {
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
#pragma omp single
    thread_counts_.assign(threads * cells, 0);
    // The chunk of thread t, as schedule(static) would cut it.
    const std::size_t lo = n * t / threads, hi = n * (t + 1) / threads;
    std::uint32_t* count = thread_counts_.data() + t * cells;
    for (std::size_t i = lo; i < hi; ++i)
      ++count[cell[i]];
#pragma omp barrier
#pragma omp single
    {
      std::uint32_t run = offset;
      for (std::size_t c = 0; c < cells; ++c) {
        start[c] = run;
        for (std::size_t u = 0; u < threads; ++u) {
          const std::uint32_t k = thread_counts_[u * cells + c];
          thread_counts_[u * cells + c] = run - offset;
          run += k;
        }
      }
      start[cells] = run;
    }
    for (std::size_t i = lo; i < hi; ++i)
      order[count[cell[i]]++] = static_cast<std::uint32_t>(i);
  }
}

template <int D>
const std::vector<std::uint32_t>& CellGrid<D>::sort_real(std::span<const Vec<D>> x, double range) {
  if (!(range > 0.0)) throw SimulationError("cell grid: range must be positive");
  if (x.size() >= std::numeric_limits<std::uint32_t>::max() / 2)
    throw SimulationError("cell grid: too many particles for 32-bit indices");
  range_ = range;
  edge_ = range * kEdgeMargin;
  n_real_ = x.size();
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
  sort_cells_by_x(ghost_x, ghost_start_, static_cast<std::uint32_t>(n_real_), order_);
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
          ghost_cell_.capacity() + order_.capacity() + thread_counts_.capacity());
}

template class CellGrid<2>;
template class CellGrid<3>;

}  // namespace flume
