// The main body of water: the largest set of real particles linked by distances of at most
// `gap`. The probes measure only this body, so that detached spray (a droplet thrown ahead of a
// front or above a column) does not count as the water's edge: an observer, like Martin & Moyce
// reading their photographs, takes the edge of the continuous body of water.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "flume/core/particle_set.hpp"

namespace flume {

// in_body[i] is 1 for the real particles of the largest linked set (ties: the set holding the
// lowest index), else 0. Breadth-first search over a hash grid of cell size `gap`: O(N).
template <int D>
std::vector<char> main_fluid_body(const ParticleSet<D>& ps, double gap) {
  const std::size_t n = ps.n_real;
  using Key = std::int64_t;
  auto cell_of = [gap](const Vec<D>& x, int k) { return static_cast<Key>(std::floor(x[k] / gap)); };
  // Each coordinate's cell index is packed in 21 bits (unsigned, so the shifts are defined for
  // negative indices too). Cells 2^21 apart share a key; that costs only a distance test, since
  // every candidate is checked against `gap`.
  auto key_of = [](const std::array<Key, D>& c) {
    std::uint64_t key = 0;
    for (int k = 0; k < D; ++k)
      key = (key << 21) | (static_cast<std::uint64_t>(c[k]) & ((std::uint64_t{1} << 21) - 1));
    return key;
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid;
  std::vector<std::array<Key, D>> cells(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k)
      cells[i][k] = cell_of(ps.x[i], k);
    grid[key_of(cells[i])].push_back(i);
  }

  std::vector<int> label(n, -1);
  std::vector<std::size_t> size_of;
  std::vector<std::size_t> queue;
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (label[seed] >= 0) continue;
    const int l = static_cast<int>(size_of.size());
    size_of.push_back(0);
    label[seed] = l;
    queue.assign(1, seed);
    while (!queue.empty()) {
      const std::size_t i = queue.back();
      queue.pop_back();
      ++size_of[l];
      // Visit the 3^D cells around i's cell.
      for (int o = 0; o < (D == 2 ? 9 : 27); ++o) {
        std::array<Key, D> c = cells[i];
        for (int k = 0, r = o; k < D; ++k, r /= 3)
          c[k] += r % 3 - 1;
        const auto it = grid.find(key_of(c));
        if (it == grid.end()) continue;
        for (std::size_t j : it->second)
          if (label[j] < 0 && norm2(ps.x[j] - ps.x[i]) <= gap * gap) {
            label[j] = l;
            queue.push_back(j);
          }
      }
    }
  }
  int best = 0;
  for (int l = 1; l < static_cast<int>(size_of.size()); ++l)
    if (size_of[l] > size_of[best]) best = l;
  std::vector<char> in_body(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    in_body[i] = label[i] == best ? 1 : 0;
  return in_body;
}

}  // namespace flume
