// CaseSpec -> Simulation: particles on the lattice of each fluid block, walls, physics and the
// scheme from the registry.
#pragma once

#include "flume/case/case_spec.hpp"
#include "flume/sim/simulation.hpp"

namespace flume {

template <int D>
Physics<D> build_physics(const CaseSpec& spec);

// The case's [[repulsive_walls]] (slopes, paddles), placed at t = 0.
template <int D>
RepulsiveWalls<D> build_repulsive_walls(const CaseSpec& spec, const Physics<D>& phys);

template <int D>
ParticleSet<D> build_particles(const CaseSpec& spec, const Physics<D>& phys);

template <int D>
Simulation<D> build_simulation(const CaseSpec& spec);

}  // namespace flume
