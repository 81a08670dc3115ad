#include "flume/bench/neighbour_count.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace flume {

template <int D>
double mean_neighbour_count(std::span<const Vec<D>> x, double radius) {
  const std::size_t n = x.size();
  if (n == 0) return 0.0;
  if (!(radius > 0.0)) throw std::invalid_argument("mean_neighbour_count: radius must be > 0");

  // Cells of side `radius` over the particles' bounding box: a neighbour of a particle is in
  // its own cell or an adjacent one.
  Vec<D> lo = x[0], hi = x[0];
  for (const auto& p : x)
    for (int k = 0; k < D; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  std::array<long, D> dims{};
  long cells = 1;
  for (int k = 0; k < D; ++k) {
    dims[static_cast<std::size_t>(k)] = static_cast<long>((hi[k] - lo[k]) / radius) + 1;
    cells *= dims[static_cast<std::size_t>(k)];
  }
  auto cell_coords = [&](const Vec<D>& p) {
    std::array<long, D> c{};
    for (int k = 0; k < D; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      c[kk] = std::min(static_cast<long>((p[k] - lo[k]) / radius), dims[kk] - 1);
    }
    return c;
  };
  auto cell_index = [&](const std::array<long, D>& c) {
    long idx = 0;
    for (int k = D - 1; k >= 0; --k)
      idx = idx * dims[static_cast<std::size_t>(k)] + c[static_cast<std::size_t>(k)];
    return static_cast<std::size_t>(idx);
  };

  // Counting sort of the particles by cell: start[c] .. start[c + 1] index `order`.
  std::vector<std::size_t> cell_of(n), start(static_cast<std::size_t>(cells) + 1, 0), order(n);
  for (std::size_t i = 0; i < n; ++i) {
    cell_of[i] = cell_index(cell_coords(x[i]));
    ++start[cell_of[i] + 1];
  }
  for (std::size_t c = 0; c < static_cast<std::size_t>(cells); ++c)
    start[c + 1] += start[c];
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      order[fill[cell_of[i]]++] = i;
  }

  const double r2 = radius * radius;
  std::size_t pairs = 0;  // ordered pairs (i, j), i != j
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = cell_coords(x[i]);
    // Walk the 3^D block of cells around c, clipped to the grid.
    std::array<long, D> off{};
    off.fill(-1);
    while (true) {
      std::array<long, D> nc{};
      bool inside = true;
      for (std::size_t k = 0; k < static_cast<std::size_t>(D); ++k) {
        nc[k] = c[k] + off[k];
        inside = inside && nc[k] >= 0 && nc[k] < dims[k];
      }
      if (inside) {
        const std::size_t cell = cell_index(nc);
        for (std::size_t s = start[cell]; s < start[cell + 1]; ++s) {
          const std::size_t j = order[s];
          if (j == i) continue;
          double d2 = 0.0;
          for (int k = 0; k < D; ++k) {
            const double d = x[i][k] - x[j][k];
            d2 += d * d;
          }
          if (d2 < r2) ++pairs;
        }
      }
      std::size_t k = 0;
      while (k < static_cast<std::size_t>(D) && ++off[k] > 1)
        off[k++] = -1;
      if (k == static_cast<std::size_t>(D)) break;
    }
  }
  return static_cast<double>(pairs) / static_cast<double>(n);
}

template double mean_neighbour_count<2>(std::span<const Vec<2>>, double);
template double mean_neighbour_count<3>(std::span<const Vec<3>>, double);

}  // namespace flume
