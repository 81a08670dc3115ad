// Conserved and monitored totals of a particle state (spec/contract.md, diagnostics.csv):
// mass; linear momentum BL (26) and angular momentum BL (29) from the staggered leap-frog
// velocity v^{n+1/2} with x^{n+1} (what leap-frog keeps exactly); kinetic energy from the
// integer-time velocity; potential energy -sum m g.x; internal (elastic) energy sum m e(rho) of
// the Tait fluid; density range. Sums run serially in particle order so that they do not
// depend on the thread count.
#pragma once

#include <string>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/schemes/physics.hpp"
#include "flume/sim/diagnostics_columns.hpp"

namespace flume {

// One row matching diagnostics_columns<D>(): time, step, dt, particles, then the totals.
template <int D>
std::vector<double> diagnostics_row(const ParticleSet<D>& ps, const Physics<D>& phys, double time,
                                    long step, double dt);

}  // namespace flume
