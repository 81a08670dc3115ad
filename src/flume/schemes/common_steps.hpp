// Per-particle steps shared by the schemes: the equation of state and the start of the force
// accumulation with the body force.
#pragma once

#include "flume/schemes/physics.hpp"
#include "flume/schemes/sweep.hpp"

namespace flume {

// p_a = p(rho_a) for the real particles, then copied to the ghosts.
template <int D>
void update_pressure(ParticleSet<D>& ps, const Physics<D>& phys, const Halo<D>& halo) {
  for_each_real(ps.n_real, [&](std::size_t i) { ps.p[i] = phys.eos.pressure(ps.rho[i]); });
  halo.update_scalar(ps, ps.p);
}

// a_a = g: the external force F_a / m_a of BL (6); the internal forces are added by the sweeps.
template <int D>
void start_accelerations(ParticleSet<D>& ps, const Physics<D>& phys) {
  for_each_real(ps.n_real, [&](std::size_t i) { ps.a[i] = phys.gravity; });
}

}  // namespace flume
