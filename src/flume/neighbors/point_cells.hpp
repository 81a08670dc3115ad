// Points binned into cells of a given side over their bounding box (a stable counting sort), so
// that the points closer to a position than that side are found among the 3^D cells around it.
// A plain search for work done once (the bench's neighbour count, the summation masses of a
// case's start), kept apart from the step's CellGrid: the bench's count must not depend on the
// search it measures.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "flume/core/vec.hpp"

namespace flume {

template <int D>
class PointCells {
 public:
  PointCells(std::span<const Vec<D>> x, double side) : side_(side) {
    const std::size_t n = x.size();
    if (n == 0) return;
    lo_ = x[0];
    Vec<D> hi = x[0];
    for (const auto& p : x)
      for (int k = 0; k < D; ++k) {
        lo_[k] = std::min(lo_[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    long cells = 1;
    for (int k = 0; k < D; ++k) {
      dims_[static_cast<std::size_t>(k)] = static_cast<long>((hi[k] - lo_[k]) / side) + 1;
      cells *= dims_[static_cast<std::size_t>(k)];
    }
    std::vector<std::size_t> cell_of(n);
    start_.assign(static_cast<std::size_t>(cells) + 1, 0);
    order_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      cell_of[i] = index(coords(x[i]));
      ++start_[cell_of[i] + 1];
    }
    for (std::size_t c = 0; c < static_cast<std::size_t>(cells); ++c)
      start_[c + 1] += start_[c];
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      order_[fill[cell_of[i]]++] = i;
  }

  // f(j) for every point j in the 3^D cells around p, clipped to the grid (p's own point
  // included), in an order fixed by the positions: the cells with the first axis fastest, each
  // cell's points in their input order. p must lie within the points' bounding box.
  template <class F>
  void for_each_near(const Vec<D>& p, F&& f) const {
    if (order_.empty()) return;
    const std::array<long, D> c = coords(p);
    std::array<long, D> off{};
    off.fill(-1);
    while (true) {
      std::array<long, D> nc{};
      bool inside = true;
      for (std::size_t k = 0; k < static_cast<std::size_t>(D); ++k) {
        nc[k] = c[k] + off[k];
        inside = inside && nc[k] >= 0 && nc[k] < dims_[k];
      }
      if (inside) {
        const std::size_t cell = index(nc);
        for (std::size_t s = start_[cell]; s < start_[cell + 1]; ++s)
          f(order_[s]);
      }
      std::size_t k = 0;
      while (k < static_cast<std::size_t>(D) && ++off[k] > 1)
        off[k++] = -1;
      if (k == static_cast<std::size_t>(D)) break;
    }
  }

 private:
  std::array<long, D> coords(const Vec<D>& p) const {
    std::array<long, D> c{};
    for (int k = 0; k < D; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      c[kk] = std::min(static_cast<long>((p[k] - lo_[k]) / side_), dims_[kk] - 1);
    }
    return c;
  }
  std::size_t index(const std::array<long, D>& c) const {
    long i = 0;
    for (int k = D - 1; k >= 0; --k)
      i = i * dims_[static_cast<std::size_t>(k)] + c[static_cast<std::size_t>(k)];
    return static_cast<std::size_t>(i);
  }

  double side_;
  Vec<D> lo_{};
  std::array<long, D> dims_{};
  std::vector<std::size_t> start_,
      order_;  // the points of cell c: order_[start_[c] .. start_[c+1])
};

}  // namespace flume
