// The evolving smoothing length, W (2.22): rho eps^n stays constant along the flow, so
//   d eps_i/dt = -(eps_i / (n rho_i)) d rho_i/dt,
// with the scheme's own density rate (methods.md errata 5: W (3.24), (3.53) print the wrong
// sign and an extra rho_i; W (3.82), (4.22) are the same rule with the sign corrected).
#pragma once

#include "flume/core/particle_set.hpp"

namespace flume {

// Sets ps.dh[i] from ps.drho[i] when the smoothing length evolves (the field is allocated).
template <int D>
void smoothing_length_rate_w222(ParticleSet<D>& ps, std::size_t i) {
  if (ps.uses(kFieldSmoothingRate)) ps.dh[i] = -ps.h[i] / (D * ps.rho[i]) * ps.drho[i];
}

}  // namespace flume
