// The cell grid the sweeps iterate over (SWIFT, Cabana, the reference step): cells of edge >= the
// interaction range, particles kept sorted by cell so that each cell's particles, and each row of
// three neighbouring cells along x, are one contiguous run of indices. Real particles are sorted
// every step (a stable counting sort, so the order depends only on the positions, never on the
// thread count); ghost copies are binned into the same cells in a run of their own after the
// real particles. Within a cell the particles are sorted by x (ties by index), so each row of
// cells is sorted by x and a sweep can cut a row's run down to the particles within one range
// of a given x by bisection. No neighbour list is stored: a sweep visits the runs directly.
// Cell index: x fastest, then y, then z. The grid has kPad empty layers of cells around the real
// particles' bounding box, so ghosts (at most two ranges beyond it) fall inside and a stencil of
// one cell around a real particle's cell never leaves the grid.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "flume/core/vec.hpp"

namespace flume {

template <int D>
class CellGrid {
 public:
  static constexpr int kPad = 3;  // empty cell layers around the real particles' bounding box

  // Lays the grid over the real particles x (cells of edge >= range) and sorts them by cell:
  // returns the permutation (new index k holds old index order[k]).
  const std::vector<std::uint32_t>& sort_real(std::span<const Vec<D>> x, double range);
  // The same for particles whose bounding box the caller knows: lo and hi, the least and the
  // largest coordinate along each axis (exactly, as the form above finds them in a pass of
  // its own; every position finite). A simulation takes them from its drift's pass.
  const std::vector<std::uint32_t>& sort_real(std::span<const Vec<D>> x, double range,
                                              const Vec<D>& lo, const Vec<D>& hi);

  // Bins the ghost positions into the grid laid by sort_real: returns the stable permutation
  // of the ghosts by cell (new ghost k is old ghost order[k]). Ghosts beyond the grid are
  // clamped to its border cells, where no real particle can reach them.
  const std::vector<std::uint32_t>& sort_ghosts(std::span<const Vec<D>> ghost_x);

  std::size_t cells() const { return cell_count_; }
  const std::array<std::size_t, D>& dims() const { return dims_; }
  // Index step of one cell along each axis.
  const std::array<std::size_t, D>& strides() const { return strides_; }
  double range() const { return range_; }

  // Real particles of cell c: [real_begin(c), real_begin(c + 1)); indices into the particle set.
  std::uint32_t real_begin(std::size_t c) const { return real_start_[c]; }
  // Ghosts of cell c: [ghost_begin(c), ghost_begin(c + 1)), as indices into the particle set
  // (the ghosts follow the real particles).
  std::uint32_t ghost_begin(std::size_t c) const { return ghost_start_[c]; }
  // The cell of sorted real particle i.
  std::size_t cell_of_real(std::size_t i) const { return real_cell_[i]; }

  // Appends to `runs` the index ranges [first, second) of the real particles of every cell
  // that reaches outside the box (lo, hi) (components may be infinite), in increasing order and
  // merged where they touch: every real particle outside the box is in one of them. The cells
  // two layers further in are taken too, so the rounding of a cell's bounds never loses one.
  void runs_outside(const Vec<D>& lo, const Vec<D>& hi,
                    std::vector<std::pair<std::uint32_t, std::uint32_t>>& runs) const;

  std::size_t bytes() const;

 private:
  std::size_t cell_of(const Vec<D>& p) const;
  // Stable counting sort of `cell` into `order`, with the cell starts (offset added) in `start`.
  void counting_sort(const std::vector<std::uint32_t>& cell, std::uint32_t offset,
                     std::vector<std::uint32_t>& start, std::vector<std::uint32_t>& order);
  // The same for fewer points than are binned in parallel (the ghosts), by one thread, in time
  // proportional to the points and the occupied cells rather than to every cell.
  void counting_sort_few(const std::vector<std::uint32_t>& cell, std::uint32_t offset,
                         std::vector<std::uint32_t>& start, std::vector<std::uint32_t>& order);

  double range_ = 0.0;
  double edge_ = 0.0;
  Vec<D> origin_{};
  std::array<std::size_t, D> dims_{};
  std::array<std::size_t, D> strides_{};
  std::size_t cell_count_ = 0;
  std::size_t n_real_ = 0;
  std::vector<std::uint32_t> real_start_;     // size cells + 1
  std::vector<std::uint32_t> ghost_start_;    // size cells + 1
  std::vector<std::uint32_t> real_cell_;      // cell of each (sorted) real particle
  std::vector<std::uint32_t> ghost_cell_;     // cell of each ghost (before sorting)
  std::vector<std::uint32_t> order_;          // the last permutation returned
  std::vector<std::uint32_t> thread_counts_;  // counting sort: per thread and cell
  std::vector<std::uint32_t> cell_totals_;    // counting sort: per thread, its cells' count
  std::vector<std::uint32_t> few_counts_;     // counting_sort_few: per cell, zero between calls
  std::vector<std::uint64_t> occupied_;       // counting_sort_few: a bit per cell
};

extern template class CellGrid<2>;
extern template class CellGrid<3>;

}  // namespace flume
