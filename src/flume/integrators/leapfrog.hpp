// Leap-frog, BL (61)-(62), with the variable step of errata.md:
//   v^{n+1/2} = v^{n-1/2} + dt_bar a^n,   dt_bar = (dt^n + dt^{n+1}) / 2,
//   x^{n+1}   = x^n + dt^{n+1} v^{n+1/2}.
// BL does not say how the density is advanced; flume staggers it like the velocity,
//   rho^{n+1/2} = rho^{n-1/2} + dt_bar (d rho/dt)^n,
// and the rates of the next step use the values predicted at the integer time,
//   v^{n+1} = v^{n+1/2} + (dt^{n+1}/2) a^n,   rho^{n+1} = rho^{n+1/2} + (dt^{n+1}/2) (d rho/dt)^n.
// The first step has dt^0 = 0, so v^{1/2} = v^0 + (dt/2) a^0. Forces depend on x^n only through
// positions at the integer level, so sum m x^{n+1} x v^{n+1/2} is kept exactly by central forces
// (BL 3.3.1): that is the staggered angular momentum the diagnostics report.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/schemes/sweep.hpp"

namespace flume {

template <int D>
class LeapFrog {
 public:
  void advance(ParticleSet<D>& ps, double dt, bool evolve_density) {
    const double dt_bar = 0.5 * (dt_prev_ + dt);
    for_each_real(ps.n_real, [&](std::size_t i) {
      ps.v_half[i] += ps.a[i] * dt_bar;
      ps.x[i] += ps.v_half[i] * dt;
      ps.v[i] = ps.v_half[i] + ps.a[i] * (0.5 * dt);
      if (evolve_density) {
        ps.rho_half[i] += dt_bar * ps.drho[i];
        ps.rho[i] = ps.rho_half[i] + 0.5 * dt * ps.drho[i];
      }
    });
    dt_prev_ = dt;
  }

 private:
  double dt_prev_ = 0.0;
};

}  // namespace flume
