// The time step. BL (63): dt = C_FL h_min / max_a (c + |v_a|), with c the reference sound speed
// (errata.md, BL (63)). BL's examples are viscous and BL gives no Courant number, so flume adds
// the usual explicit-diffusion limit dt <= 0.125 h^2 / nu (Morris et al. 1997) when mu > 0 and
// the body-force limit dt <= 0.25 sqrt(h / |a|) (W (3.89)); C_FL comes from the case file.
// Minimum reductions are exact, so the step does not depend on the thread count.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "flume/core/particle_set.hpp"
#include "flume/schemes/physics.hpp"

namespace flume {

template <int D>
double cfl_time_step(const ParticleSet<D>& ps, const Physics<D>& phys, double cfl) {
  const double c0 = phys.eos.reference_sound_speed();
  double dt_c = std::numeric_limits<double>::max();
  double dt_f = std::numeric_limits<double>::max();  // min h / |a|, s^2
  double h_min = std::numeric_limits<double>::max();
  const auto n = static_cast<long>(ps.n_real);
  // Without a branch, so that the loop vectorises: h / |a| is +infinity where a = 0, and the
  // square root of the body-force limit is taken once, of the minimum.
#pragma omp parallel for simd schedule(static) reduction(min : dt_c, dt_f, h_min)
  for (long ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    dt_c = std::min(dt_c, ps.h[i] / (c0 + norm(ps.v[i])));
    dt_f = std::min(dt_f, ps.h[i] / norm(ps.a[i]));
    h_min = std::min(h_min, ps.h[i]);
  }
  double dt = std::min(cfl * dt_c, 0.25 * std::sqrt(dt_f));
  if (phys.mu > 0.0) dt = std::min(dt, 0.125 * h_min * h_min * phys.eos.rho0 / phys.mu);
  return dt;
}

}  // namespace flume
