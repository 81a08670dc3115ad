// Neighbour search by a uniform cell list (cell edge >= cutoff) built with a counting sort of
// the particles by cell, as in SWIFT and Cabana: O(N) per rebuild, buffers reused between
// rebuilds. The cell order also gives the order in which real particles are re-sorted in memory
// so that neighbours sit close together.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "flume/core/vec.hpp"
#include "flume/neighbors/neighbor_list.hpp"

namespace flume {

template <int D>
class CellList {
 public:
  // Bins the points x into cells of edge >= cutoff covering their bounding box.
  void build(std::span<const Vec<D>> x, double cutoff);

  // Fills out with, for each query point i < n_query, every point j (i itself included) with
  // |x_i - x_j| < cutoff, in ascending cell order then ascending index. Parallel over i.
  void find_neighbors(std::span<const Vec<D>> x, std::size_t n_query, NeighborList& out) const;

  // The indices [0, n) sorted by cell (stable): used to re-order real particles in memory.
  std::vector<std::size_t> cell_order(std::size_t n) const;

  std::size_t cells() const { return cell_start_.empty() ? 0 : cell_start_.size() - 1; }

 private:
  std::size_t cell_of(const Vec<D>& p) const;

  double cutoff_ = 0.0;
  double edge_ = 0.0;  // cell edge, a hair wider than the cut-off
  Vec<D> origin_{};
  std::array<std::size_t, D> dims_{};
  std::vector<std::size_t> cell_start_;      // size cells + 1
  std::vector<std::size_t> sorted_;          // point indices sorted by cell
  std::vector<std::size_t> point_cell_;      // cell of each point
  mutable std::vector<std::size_t> counts_;  // per-query neighbour counts (reused buffer)
};

extern template class CellList<2>;
extern template class CellList<3>;

}  // namespace flume
