// The O(N^2) reference neighbour search the tests check the cell list against.
#pragma once

#include <span>

#include "flume/core/vec.hpp"
#include "flume/neighbors/neighbor_list.hpp"

namespace flume {

template <int D>
NeighborList brute_force_neighbors(std::span<const Vec<D>> x, std::size_t n_query, double cutoff) {
  NeighborList out;
  out.offset.push_back(0);
  for (std::size_t i = 0; i < n_query; ++i) {
    for (std::size_t j = 0; j < x.size(); ++j)
      if (norm2(x[i] - x[j]) < cutoff * cutoff) out.index.push_back(static_cast<std::uint32_t>(j));
    out.offset.push_back(out.index.size());
  }
  return out;
}

}  // namespace flume
