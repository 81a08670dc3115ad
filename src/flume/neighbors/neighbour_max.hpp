// The largest value of a pair function over each real particle's neighbours, for the one rule
// that needs a maximum over pairs: the time step W (3.88). The sweep driver (schemes/sweep.hpp)
// only sums (its lanes fold partial sums), so this walks the cell grid of the step directly:
// for each real i, every particle j != i (real or ghost) of the 3^D cells around i's cell
// within `range`. Each i is visited from its own side only and writes only out[i], and a
// maximum is exact in any order: the result does not depend on the thread count. It visits
// every pair twice and is not vectorised: an option's cost, not the default's.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/neighbors/cell_grid.hpp"

namespace flume {

template <int D, class F>
void neighbour_max(const CellGrid<D>& grid, const ParticleSet<D>& ps, double range,
                   std::vector<double>& out, const F& f) {
  // Offsets of the 3^D cells around a cell, from the grid's strides.
  std::array<long, 27> around{};
  std::size_t n_around = 0;
  {
    std::array<int, D> o{};
    o.fill(-1);
    while (true) {
      long off = 0;
      for (int k = 0; k < D; ++k)
        off += o[static_cast<std::size_t>(k)] *
               static_cast<long>(grid.strides()[static_cast<std::size_t>(k)]);
      around[n_around++] = off;
      int k = 0;
      while (k < D && ++o[static_cast<std::size_t>(k)] > 1)
        o[static_cast<std::size_t>(k++)] = -1;
      if (k == D) break;
    }
  }
  const double range2 = range * range;
  const auto n = static_cast<long>(ps.n_real);
#pragma omp parallel for schedule(static)
  for (long ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const auto c = static_cast<long>(grid.cell_of_real(i));
    double best = 0.0;
    auto visit = [&](std::size_t jb, std::size_t je) {
      for (std::size_t j = jb; j < je; ++j)
        if (j != i && norm2(ps.x[i] - ps.x[j]) < range2) best = std::max(best, f(i, j));
    };
    for (std::size_t a = 0; a < n_around; ++a) {
      const auto cell = static_cast<std::size_t>(c + around[a]);
      visit(grid.real_begin(cell), grid.real_begin(cell + 1));
      visit(grid.ghost_begin(cell), grid.ghost_begin(cell + 1));
    }
    out[i] = best;
  }
}

}  // namespace flume
