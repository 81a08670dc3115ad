#include "flume/neighbors/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "flume/core/error.hpp"

namespace flume {

namespace {
// A grid larger than this means particles are spread absurdly far apart (a particle escaped):
// refuse rather than allocate gigabytes.
constexpr std::size_t kMaxCells = std::size_t{1} << 24;
// Cells are this much wider than the cut-off, so that rounding in (x - origin) / edge can never
// put two points closer than the cut-off into cells two apart (the rounding error of the scaled
// coordinate is a few ulps of at most 2^24, far below 1e-6).
constexpr double kEdgeMargin = 1.0 + 1e-6;
}  // namespace

template <int D>
std::size_t CellList<D>::cell_of(const Vec<D>& p) const {
  std::size_t idx = 0;
  for (int k = D - 1; k >= 0; --k) {
    const double s = (p[k] - origin_[k]) / edge_;
    auto c = static_cast<std::size_t>(std::max(0.0, s));
    c = std::min(c, dims_[k] - 1);
    idx = idx * dims_[k] + c;
  }
  return idx;
}

template <int D>
void CellList<D>::build(std::span<const Vec<D>> x, double cutoff) {
  if (!(cutoff > 0.0)) throw SimulationError("cell list: cutoff must be positive");
  cutoff_ = cutoff;
  edge_ = cutoff * kEdgeMargin;
  Vec<D> lo, hi;
  for (int k = 0; k < D; ++k) {
    lo[k] = std::numeric_limits<double>::max();
    hi[k] = std::numeric_limits<double>::lowest();
  }
  for (const auto& p : x) {
    for (int k = 0; k < D; ++k) {
      if (!std::isfinite(p[k])) throw SimulationError("cell list: non-finite particle position");
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  std::size_t ncells = 1;
  for (int k = 0; k < D; ++k) {
    if (x.empty()) lo[k] = hi[k] = 0.0;
    origin_[k] = lo[k];
    const double extent = (hi[k] - lo[k]) / edge_;
    if (extent > static_cast<double>(kMaxCells))
      throw SimulationError(
          fmt::format("cell list: particles spread over {:.3g} cut-off lengths "
                      "along axis {}; a particle has escaped",
                      extent, k));
    dims_[k] = static_cast<std::size_t>(extent) + 1;
    ncells *= dims_[k];
    if (ncells > kMaxCells)
      throw SimulationError("cell list: too many cells; particles are spread too far apart");
  }

  // Counting sort by cell, stable in the point index.
  cell_start_.assign(ncells + 1, 0);
  point_cell_.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    point_cell_[i] = cell_of(x[i]);
    ++cell_start_[point_cell_[i] + 1];
  }
  for (std::size_t c = 0; c < ncells; ++c)
    cell_start_[c + 1] += cell_start_[c];
  sorted_.resize(x.size());
  counts_.assign(ncells, 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::size_t c = point_cell_[i];
    sorted_[cell_start_[c] + counts_[c]++] = i;
  }
}

template <int D>
std::vector<std::size_t> CellList<D>::cell_order(std::size_t n) const {
  std::vector<std::size_t> order;
  order.reserve(n);
  for (std::size_t idx : sorted_)
    if (idx < n) order.push_back(idx);
  return order;
}

template <int D>
void CellList<D>::find_neighbors(std::span<const Vec<D>> x, std::size_t n_query,
                                 NeighborList& out) const {
  const double cut2 = cutoff_ * cutoff_;
  // Visits every point in the 3^D cells around point i, in a fixed order.
  auto visit = [&](std::size_t i, auto&& on_neighbor) {
    std::array<std::size_t, D> ci{};
    std::size_t rest = point_cell_[i];
    for (int k = 0; k < D; ++k) {
      ci[k] = rest % dims_[k];
      rest /= dims_[k];
    }
    std::array<int, D> off{};
    for (int k = 0; k < D; ++k)
      off[k] = -1;
    while (true) {
      bool inside = true;
      std::size_t cell = 0;
      for (int k = D - 1; k >= 0; --k) {
        const auto c = static_cast<long>(ci[k]) + off[k];
        if (c < 0 || c >= static_cast<long>(dims_[k])) {
          inside = false;
          break;
        }
        cell = cell * dims_[k] + static_cast<std::size_t>(c);
      }
      if (inside) {
        for (std::size_t s = cell_start_[cell]; s < cell_start_[cell + 1]; ++s) {
          const std::size_t j = sorted_[s];
          if (norm2(x[i] - x[j]) < cut2) on_neighbor(j);
        }
      }
      int k = 0;
      while (k < D && off[k] == 1)
        off[k++] = -1;
      if (k == D) break;
      ++off[k];
    }
  };

  counts_.resize(n_query);
  const auto nq = static_cast<long>(n_query);
#pragma omp parallel for schedule(static)
  for (long qi = 0; qi < nq; ++qi) {
    const auto i = static_cast<std::size_t>(qi);
    std::size_t c = 0;
    visit(i, [&c](std::size_t) { ++c; });
    counts_[i] = c;
  }
  out.offset.resize(n_query + 1);
  out.offset[0] = 0;
  for (std::size_t i = 0; i < n_query; ++i)
    out.offset[i + 1] = out.offset[i] + counts_[i];
  out.index.resize(out.offset[n_query]);
#pragma omp parallel for schedule(static)
  for (long qi = 0; qi < nq; ++qi) {
    const auto i = static_cast<std::size_t>(qi);
    std::size_t w = out.offset[i];
    visit(i, [&](std::size_t j) { out.index[w++] = static_cast<std::uint32_t>(j); });
  }
}

template class CellList<2>;
template class CellList<3>;

}  // namespace flume
