// Leap-frog, BL (61)-(62), with the variable step of errata.md:
//   v^{n+1/2} = v^{n-1/2} + dt_bar a^n,   dt_bar = (dt^n + dt^{n+1}) / 2,        (kick)
//   x^{n+1}   = x^n + dt^{n+1} v^{n+1/2}.                                        (drift)
// The first step has dt^0 = 0, so v^{1/2} = v^0 + (dt/2) a^0.
// BL does not say how the density is advanced. flume keeps rho with x at integer levels and
// advances it with the velocity of the kick,
//   rho^{n+1} = rho^n + dt^{n+1} (d rho/dt)(x^n, v^{n+1/2}),
// the symplectic-Euler pairing of the acoustic (rho, v) system: stable for dt below the CFL
// limit. (Advancing rho alongside v from rates at the integer time, with v and rho predicted
// there, is the forward-Euler pairing and lets still water drift into a growing acoustic mode.)
// The velocity-dependent terms of a^n (viscosity) use the prediction v^n = v^{n-1/2} +
// (dt^n/2) a^{n-1}. Forces depend on positions only through x^n, so sum m x^{n+1} x v^{n+1/2} is
// kept exactly by central forces (BL 3.3.1): the staggered angular momentum of the diagnostics.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/schemes/sweep.hpp"

namespace flume {

template <int D>
class LeapFrog {
 public:
  // BL (61): v^{n+1/2} = v^{n-1/2} + dt_bar a^n, for the step dt = dt^{n+1} about to be taken.
  void kick(ParticleSet<D>& ps, double dt) {
    const double dt_bar = 0.5 * (dt_prev_ + dt);
    for_each_real(ps.n_real, [&](std::size_t i) { ps.v_half[i] += ps.a[i] * dt_bar; });
    dt_prev_ = dt;
  }

  // rho^{n+1} = rho^n + dt drho, drho evaluated after the kick.
  void advance_density(ParticleSet<D>& ps, double dt) const {
    for_each_real(ps.n_real, [&](std::size_t i) { ps.rho[i] += dt * ps.drho[i]; });
  }

  // BL (62): x^{n+1} = x^n + dt v^{n+1/2}; and the prediction v^{n+1} = v^{n+1/2} + (dt/2) a^n
  // used by the velocity-dependent terms of the next step and by the kinetic energy.
  void drift(ParticleSet<D>& ps, double dt) const {
    for_each_real(ps.n_real, [&](std::size_t i) {
      ps.x[i] += ps.v_half[i] * dt;
      ps.v[i] = ps.v_half[i] + ps.a[i] * (0.5 * dt);
    });
  }

  // kick then drift in one pass over the particles (the same operations on each particle in
  // the same order, so the same bits): for schemes whose density does not need the kick's
  // velocity in between. The two passes read and wrote the state twice.
  void kick_and_drift(ParticleSet<D>& ps, double dt) {
    const double dt_bar = 0.5 * (dt_prev_ + dt);
    for_each_real(ps.n_real, [&](std::size_t i) {
      ps.v_half[i] += ps.a[i] * dt_bar;
      ps.x[i] += ps.v_half[i] * dt;
      ps.v[i] = ps.v_half[i] + ps.a[i] * (0.5 * dt);
    });
    dt_prev_ = dt;
  }

  // One whole step with the rates already in ps (a, and drho when evolve_density).
  void advance(ParticleSet<D>& ps, double dt, bool evolve_density) {
    if (!evolve_density) return kick_and_drift(ps, dt);
    kick(ps, dt);
    advance_density(ps, dt);
    drift(ps, dt);
  }

 private:
  double dt_prev_ = 0.0;
};

}  // namespace flume
