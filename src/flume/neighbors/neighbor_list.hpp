// Compressed (CSR) neighbour lists: the neighbours of query particle i are
// index[offset[i] .. offset[i+1]). Each list is in a fixed order that depends only on the particle
// positions and indices, never on the thread count, so every sum over neighbours is reproducible.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace flume {

struct NeighborList {
  std::vector<std::size_t> offset;   // size n_query + 1
  std::vector<std::uint32_t> index;  // neighbour indices, the query itself included

  std::size_t queries() const { return offset.empty() ? 0 : offset.size() - 1; }
  std::span<const std::uint32_t> of(std::size_t i) const {
    return {index.data() + offset[i], offset[i + 1] - offset[i]};
  }
};

}  // namespace flume
