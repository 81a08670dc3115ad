// The rates of a scheme on a particle set, computed through the same path a simulation step
// takes (ghosts, neighbours, the scheme's groups), but without advancing anything. The physics
// tests go through this one function, so that they outlive changes of the sweep driver: the
// particle order the caller built is kept (results are written back to the caller's indices).
#pragma once

#include "flume/boundaries/box_walls.hpp"
#include "flume/neighbors/cell_list.hpp"
#include "flume/schemes/scheme.hpp"

namespace flume::test {

// Fills, for the real particles of ps: ps.a (and ps.rho, ps.p for a summation density; ps.p,
// ps.grad_v, ps.stress, ps.shepard, ps.gamma, ps.L as the scheme computes them) and, for a
// scheme that evolves density, ps.drho evaluated with the velocity field ps.v_half. Ghosts of
// the walls (if any) are built as a simulation step builds them and dropped afterwards.
template <int D>
void compute_rates(const Scheme<D>& scheme, ParticleSet<D>& ps,
                   const BoxWalls<D>* walls = nullptr) {
  double h_max = 0.0;
  for (std::size_t i = 0; i < ps.n_real; ++i)
    h_max = std::max(h_max, ps.h[i]);
  const double range = scheme.support() * h_max;
  Halo<D> halo;
  if (walls) walls->build_halo(ps, range, halo);
  halo.append_ghosts(ps);
  CellList<D> cells;
  NeighborList nl;
  cells.build(ps.x, range);
  cells.find_neighbors(ps.x, ps.n_real, nl);
  scheme.compute_accelerations(ps, nl, halo);
  if (scheme.evolves_density()) scheme.compute_density_rate(ps, nl, halo);
  ps.drop_ghosts();
}

// Applies the scheme's density filter (the Shepard filter W (6.3)) once to the real particles of
// ps, the ghosts of the walls (if any) taking part as in a simulation step.
template <int D>
void filter_density(const Scheme<D>& scheme, ParticleSet<D>& ps,
                    const BoxWalls<D>* walls = nullptr) {
  double h_max = 0.0;
  for (std::size_t i = 0; i < ps.n_real; ++i)
    h_max = std::max(h_max, ps.h[i]);
  const double range = scheme.support() * h_max;
  Halo<D> halo;
  if (walls) walls->build_halo(ps, range, halo);
  halo.append_ghosts(ps);
  CellList<D> cells;
  NeighborList nl;
  cells.build(ps.x, range);
  cells.find_neighbors(ps.x, ps.n_real, nl);
  scheme.filter_density(ps, nl, halo);
  ps.drop_ghosts();
}

}  // namespace flume::test
