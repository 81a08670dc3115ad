// Masses from the summation density (particles.mass = "summation"):
//   m_a = rho_a / sum_b W(|x_a - x_b|, h_a),  the sum over every particle b, a itself included,
// so that BL (1) with the kernel of particle a, rho_a = sum_b m_b W_ab, starts near the block's
// density rho_a at every particle instead of the ~60 % a surface particle reads with m = rho
// dx^D (BL 5.2's drop "with initial density 10^3": a summation density only has that start
// with masses set this way). It is not exact, since the masses of a's neighbours differ from
// m_a; the case checks refuse it beside a wall, whose ghosts the sum does not have.
// The neighbours come from cells of the kernel's support (neighbors/point_cells.hpp); each sum is
// taken in an order fixed by the positions, so the masses do not depend on the thread count.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/neighbors/point_cells.hpp"

namespace flume {

template <int D, class Kernel>
std::vector<double> summation_masses(const ParticleSet<D>& ps) {
  const std::size_t n = ps.n_real;
  std::vector<double> masses(n, 0.0);
  if (n == 0) return masses;
  double h_max = 0.0;
  for (std::size_t a = 0; a < n; ++a)
    h_max = std::max(h_max, ps.h[a]);
  const PointCells<D> cells(std::span<const Vec<D>>(ps.x.data(), n), Kernel::support * h_max);
#pragma omp parallel for schedule(static)
  for (long aa = 0; aa < static_cast<long>(n); ++aa) {
    const auto a = static_cast<std::size_t>(aa);
    double sum = 0.0;
    cells.for_each_near(ps.x[a],
                        [&](std::size_t b) { sum += Kernel::w(norm(ps.x[a] - ps.x[b]), ps.h[a]); });
    masses[a] = ps.rho[a] / sum;
  }
  return masses;
}

}  // namespace flume
