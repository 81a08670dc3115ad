// Masses from the summation density (particles.mass = "summation"):
//   m_a = rho_a / sum_b W(|x_a - x_b|, h_a),  the sum over every particle b, a itself included,
// so that BL (1) with the kernel of particle a, rho_a = sum_b m_b W_ab, starts near the block's
// density rho_a at every particle instead of the ~60 % a surface particle reads with m = rho
// dx^D (BL 5.2's drop "with initial density 10^3": a summation density only has that start
// with masses set this way). It is not exact, since the masses of a's neighbours differ from
// m_a; the case checks refuse it beside a wall, whose ghosts the sum does not have.
// The neighbours come from cells of the kernel's support; each sum is taken over the cells in a
// fixed order, so the masses do not depend on the thread count.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "flume/core/particle_set.hpp"

namespace flume {

template <int D, class Kernel>
std::vector<double> summation_masses(const ParticleSet<D>& ps) {
  const std::size_t n = ps.n_real;
  std::vector<double> masses(n, 0.0);
  if (n == 0) return masses;
  double h_max = 0.0;
  Vec<D> lo = ps.x[0];
  for (std::size_t a = 0; a < n; ++a) {
    h_max = std::max(h_max, ps.h[a]);
    for (int k = 0; k < D; ++k)
      lo[k] = std::min(lo[k], ps.x[a][k]);
  }
  const double cell = Kernel::support * h_max;
  std::array<long, D> dims{};
  Vec<D> hi = lo;
  for (std::size_t a = 0; a < n; ++a)
    for (int k = 0; k < D; ++k)
      hi[k] = std::max(hi[k], ps.x[a][k]);
  long cells = 1;
  for (int k = 0; k < D; ++k) {
    dims[static_cast<std::size_t>(k)] = static_cast<long>((hi[k] - lo[k]) / cell) + 1;
    cells *= dims[static_cast<std::size_t>(k)];
  }
  const auto coord = [&](const Vec<D>& x, int k) {
    return std::min(static_cast<long>((x[k] - lo[k]) / cell),
                    dims[static_cast<std::size_t>(k)] - 1);
  };
  const auto index = [&](const std::array<long, D>& c) {
    long i = 0;
    for (int k = D - 1; k >= 0; --k)
      i = i * dims[static_cast<std::size_t>(k)] + c[static_cast<std::size_t>(k)];
    return static_cast<std::size_t>(i);
  };
  // Particles bucketed by cell (a counting sort, stable: each cell keeps the particles' order).
  std::vector<std::size_t> start(static_cast<std::size_t>(cells) + 1, 0), order(n);
  std::vector<std::size_t> cell_of(n);
  for (std::size_t a = 0; a < n; ++a) {
    std::array<long, D> c{};
    for (int k = 0; k < D; ++k)
      c[static_cast<std::size_t>(k)] = coord(ps.x[a], k);
    cell_of[a] = index(c);
    ++start[cell_of[a] + 1];
  }
  for (std::size_t c = 0; c < static_cast<std::size_t>(cells); ++c)
    start[c + 1] += start[c];
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t a = 0; a < n; ++a)
      order[fill[cell_of[a]]++] = a;
  }
  long around = 1;
  for (int k = 0; k < D; ++k)
    around *= 3;
#pragma omp parallel for schedule(static)
  for (long aa = 0; aa < static_cast<long>(n); ++aa) {
    const auto a = static_cast<std::size_t>(aa);
    std::array<long, D> c{};
    for (int k = 0; k < D; ++k)
      c[static_cast<std::size_t>(k)] = coord(ps.x[a], k);
    double sum = 0.0;
    for (long m = 0; m < around; ++m) {
      std::array<long, D> o = c;
      long rest = m;
      bool valid = true;
      for (int k = 0; k < D; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        o[kk] += rest % 3 - 1;
        rest /= 3;
        valid = valid && o[kk] >= 0 && o[kk] < dims[kk];
      }
      if (!valid) continue;
      const std::size_t oc = index(o);
      for (std::size_t q = start[oc]; q < start[oc + 1]; ++q)
        sum += Kernel::w(norm(ps.x[a] - ps.x[order[q]]), ps.h[a]);
    }
    masses[a] = ps.rho[a] / sum;
  }
  return masses;
}

}  // namespace flume
