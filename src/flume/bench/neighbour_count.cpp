#include "flume/bench/neighbour_count.hpp"

#include <cstddef>
#include <stdexcept>

#include "flume/neighbors/point_cells.hpp"

namespace flume {

template <int D>
double mean_neighbour_count(std::span<const Vec<D>> x, double radius) {
  const std::size_t n = x.size();
  if (n == 0) return 0.0;
  if (!(radius > 0.0)) throw std::invalid_argument("mean_neighbour_count: radius must be > 0");

  // Cells of side `radius` over the particles' bounding box: a neighbour of a particle is in
  // its own cell or an adjacent one.
  const PointCells<D> cells(x, radius);
  const double r2 = radius * radius;
  std::size_t pairs = 0;  // ordered pairs (i, j), i != j
  for (std::size_t i = 0; i < n; ++i)
    cells.for_each_near(x[i], [&](std::size_t j) {
      double d2 = 0.0;
      for (int k = 0; k < D; ++k) {
        const double d = x[i][k] - x[j][k];
        d2 += d * d;
      }
      if (j != i && d2 < r2) ++pairs;
    });
  return static_cast<double>(pairs) / static_cast<double>(n);
}

template double mean_neighbour_count<2>(std::span<const Vec<2>>, double);
template double mean_neighbour_count<3>(std::span<const Vec<3>>, double);

}  // namespace flume
