// The rates of a scheme on a particle set, computed through the same path a simulation step
// takes (cell sort, ghosts, the scheme's groups), but without advancing anything. The physics
// tests go through this one function, so that they outlive changes of the sweep driver: the
// particle order the caller built is kept (results are written back to the caller's indices).
#pragma once

#include <algorithm>
#include <numeric>

#include "flume/boundaries/box_walls.hpp"
#include "flume/neighbors/cell_grid.hpp"
#include "flume/schemes/scheme.hpp"
#include "flume/schemes/sweep_workspace.hpp"

namespace flume::test {

// Sorts a copy of ps by cell (cells of support * max h), appends the ghosts of the walls, runs
// f(copy, ctx, halo), then copies every field back to the caller's order (ghosts dropped).
template <int D, class F>
void in_cell_order(double support, ParticleSet<D>& ps, const BoxWalls<D>* walls, F&& f) {
  double h_max = 0.0, h_min = ps.n_real ? ps.h[0] : 0.0;
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    h_max = std::max(h_max, ps.h[i]);
    h_min = std::min(h_min, ps.h[i]);
  }
  const double range = support * h_max;
  ps.drop_ghosts();
  CellGrid<D> grid;
  const std::vector<std::uint32_t> order =
      grid.sort_real(std::span<const Vec<D>>(ps.x.data(), ps.n_real), range);
  ParticleSet<D> sorted = ps;
  sorted.for_each_field([&](auto& field) {
    auto copy = field;
    for (std::size_t k = 0; k < order.size(); ++k)
      field[k] = copy[order[k]];
  });
  Halo<D> halo;
  if (walls) walls->build_halo(sorted, range, halo, grid);  // as a simulation step builds it
  std::vector<Vec<D>> gx(halo.size());
  for (std::size_t g = 0; g < halo.size(); ++g)
    gx[g] = halo.position(sorted, g);
  halo.reorder(grid.sort_ghosts(gx));
  halo.append_ghosts(sorted);
  SweepWorkspace work;
  const SweepContext<D> ctx{grid, work, h_min == h_max ? h_max : 0.0, nullptr};
  f(sorted, ctx, halo);
  sorted.drop_ghosts();
  // Back to the caller's order: sorted index k is the caller's index order[k].
  auto out = sorted;
  out.for_each_field([&](auto& field) {
    auto copy = field;
    for (std::size_t k = 0; k < order.size(); ++k)
      field[order[k]] = copy[k];
  });
  ps = std::move(out);
}

// Fills, for the real particles of ps: ps.a (and ps.rho, ps.p for a summation density; ps.p,
// ps.grad_v, ps.stress, ps.shepard, ps.gamma, ps.L as the scheme computes them) and, for a
// scheme that evolves density (energy, smoothing length), ps.drho (ps.de, ps.dh) evaluated with
// the velocity field ps.v_half. Ghosts of
// the walls (if any) are built as a simulation step builds them and dropped afterwards.
template <int D>
void compute_rates(const Scheme<D>& scheme, ParticleSet<D>& ps,
                   const BoxWalls<D>* walls = nullptr) {
  in_cell_order(scheme.support(), ps, walls,
                [&](ParticleSet<D>& s, const SweepContext<D>& ctx, const Halo<D>& halo) {
                  // The time step it returns is not needed here (the CFL number is any).
                  scheme.compute_accelerations(s, ctx, halo, StepLimit<D>{});
                  scheme.compute_state_rates(s, ctx, halo, s.v_half);
                });
}

// Applies the scheme's density filter (the Shepard filter W (6.3), or its first-order form) once
// to the real particles of ps, the ghosts of the walls (if any) taking part as in a simulation
// step.
template <int D>
void filter_density(const Scheme<D>& scheme, ParticleSet<D>& ps, const BoxWalls<D>* walls = nullptr,
                    DensityFilter kind = DensityFilter::shepard) {
  in_cell_order(scheme.support(), ps, walls,
                [&](ParticleSet<D>& s, const SweepContext<D>& ctx, const Halo<D>& halo) {
                  scheme.filter_density(s, ctx, halo, kind);
                });
}

}  // namespace flume::test
