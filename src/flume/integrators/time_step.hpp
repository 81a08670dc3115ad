// The time step. BL (63): dt = C_FL h_min / max_a (c + |v_a|), with c the reference sound speed
// (errata.md, BL (63)); for a gas, whose reference speed is zero, each particle's own c_a
// (W (3.88)'s c_i). BL's examples are viscous and BL gives no Courant number, so flume adds
// the usual explicit-diffusion limit dt <= 0.125 h^2 / nu (Morris et al. 1997) when mu > 0 and
// the body-force limit dt <= 0.25 sqrt(h / |a|) (W (3.89)); C_FL comes from the case file.
// Each particle a has its own limit dt_a, the smallest of the three with its own h_a, v_a and
// a_a; the step is min_a dt_a. Every operation in dt_a is monotone in h_a, |v_a| and |a_a|, so
// this is the same number, bit for bit, as the three minima over the particles taken first.
// Minimum reductions are exact, so the step does not depend on the thread count.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "flume/core/particle_set.hpp"
#include "flume/schemes/physics.hpp"

namespace flume {

template <int D>
struct StepLimit {
  double cfl = 0.3;  // C_FL
  double c0 = 0.0;   // reference sound speed, m/s; 0: each particle's own c (a gas, W (3.88))
  double rho0 = 0.0;
  double mu = 0.0;  // dynamic viscosity, Pa s

  StepLimit() = default;
  StepLimit(const Physics<D>& phys, double courant)
      : cfl(courant), c0(phys.eos.reference_sound_speed()), rho0(phys.eos.rho0), mu(phys.mu) {}

  // min dt_a over the particles [b, e), s (+infinity if none). Without a branch, so that the
  // loop vectorises: h / |a| is +infinity where a = 0, and the viscous limit is +infinity
  // where mu = 0.
  double least(const ParticleSet<D>& ps, std::size_t b, std::size_t e) const {
    const double* __restrict h = ps.h.data();
    const double* __restrict sound = ps.c.data();
    const bool local = c0 == 0.0;
    const Vec<D>* __restrict v = ps.v.data();
    const Vec<D>* __restrict acc = ps.a.data();
    const double courant = cfl, c = c0;
    double dt = std::numeric_limits<double>::infinity();
    const auto n = static_cast<long>(e);
#pragma omp simd reduction(min : dt)
    for (auto a = static_cast<long>(b); a < n; ++a) {
      const double acoustic = courant * (h[a] / ((local ? sound[a] : c) + norm(v[a])));
      const double body = 0.25 * std::sqrt(h[a] / norm(acc[a]));
      const double viscous = 0.125 * h[a] * h[a] * rho0 / mu;
      dt = std::min(dt, std::min(std::min(acoustic, body), viscous));
    }
    return dt;
  }
};

// min_a dt_a over the real particles. (A simulation takes it block by block in the force
// sweep's pass, sweep_least.)
template <int D>
double cfl_time_step(const ParticleSet<D>& ps, const Physics<D>& phys, double cfl) {
  const StepLimit<D> limit(phys, cfl);
  return limit.least(ps, 0, ps.n_real);
}

}  // namespace flume
