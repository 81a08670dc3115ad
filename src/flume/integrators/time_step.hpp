// The time step, one of two rules (scheme.time_step):
// - BL (63): dt = C_FL h_min / max_a (c + |v_a|), with c the reference sound speed (errata.md,
//   BL (63)); for a gas, whose reference speed is zero, each particle's own c_a (W (3.88)'s
//   c_i). BL's examples are viscous and BL gives no Courant number, so flume adds the body-force
//   limit dt <= 0.25 sqrt(h / |a|) (W (3.89)); C_FL comes from the case file.
// - W (3.88)-(3.90): dt = C_FL min(dt_c, dt_F), C_FL = 0.3 in W,
//     dt_c = min_i h_i / (c_i + max_j |h_i u_ij . x_ij / (x_ij . x_ij)|),   dt_F = min_i sqrt(h_i /
//     |a_i|),
//   with the local sound speed c_i and the pair maximum s_i = max_j |...| in ps.signal
//   (signal_speed_w388, taken before the rates; |x_ij|^2 + 0.01 h_i^2 as in W (3.19), so that two
//   particles at one place do not make it infinite).
// Both add the explicit-diffusion limit dt <= 0.125 h^2 / (nu + nu_t) (Morris et al. 1997) when
// there is a viscosity: mu / rho0, and LES's eddy viscosity nu_t of each particle (W (5.19)).
// Each particle a has its own limit dt_a, the smallest of its terms with its own h_a, v_a, a_a;
// the step is min_a dt_a. Every operation in dt_a is monotone in h_a, |v_a| and |a_a|, so
// this is the same number, bit for bit, as the minima over the particles taken first.
// Minimum reductions are exact, so the step does not depend on the thread count.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "flume/core/particle_set.hpp"
#include "flume/neighbors/cell_grid.hpp"
#include "flume/neighbors/neighbour_max.hpp"
#include "flume/schemes/physics.hpp"

namespace flume {

enum class StepRule { bl63, w388 };

template <int D>
struct StepLimit {
  double cfl = 0.3;  // C_FL
  double c0 = 0.0;   // reference sound speed, m/s; 0: each particle's own c (a gas, W (3.88))
  double rho0 = 0.0;
  double mu = 0.0;    // dynamic viscosity, Pa s
  bool eddy = false;  // add each particle's eddy viscosity ps.nu_t (LES-SPH)
  StepRule rule = StepRule::bl63;

  StepLimit() = default;
  StepLimit(const Physics<D>& phys, double courant, StepRule r = StepRule::bl63)
      : cfl(courant),
        c0(phys.eos.reference_sound_speed()),
        rho0(phys.eos.rho0),
        mu(phys.mu),
        eddy(phys.les.on),
        rule(r) {}

  // The optional fields the rule reads (ParticleSet::use_only).
  unsigned fields() const { return rule == StepRule::w388 ? kFieldSignal : 0u; }

  // min dt_a over the particles [b, e), s (+infinity if none). uniform_h > 0 says that every
  // particle has that smoothing length (SweepContext::uniform_h).
  double least(const ParticleSet<D>& ps, std::size_t b, std::size_t e,
               double uniform_h = 0.0) const {
    if (uniform_h > 0.0 && rule == StepRule::bl63 && !eddy && c0 != 0.0)
      return least_uniform(ps, b, e, uniform_h);
    if (rule == StepRule::w388)
      return eddy ? least_of<true, true>(ps, b, e) : least_of<true, false>(ps, b, e);
    return eddy ? least_of<false, true>(ps, b, e) : least_of<false, false>(ps, b, e);
  }

 private:
  // Without a branch, so that the loop vectorises: h / |a| is +infinity where a = 0, and the
  // viscous limit is +infinity where mu (and nu_t) = 0.
  template <bool W388, bool Eddy>
  double least_of(const ParticleSet<D>& ps, std::size_t b, std::size_t e) const {
    const double* __restrict h = ps.h.data();
    const double* __restrict sound = ps.c.data();
    const double* __restrict signal = W388 ? ps.signal.data() : nullptr;
    const double* __restrict nu_t = Eddy ? ps.nu_t.data() : nullptr;
    const bool local = c0 == 0.0;
    const Vec<D>* __restrict v = ps.v.data();
    const Vec<D>* __restrict acc = ps.a.data();
    const double courant = cfl, c = c0;
    double dt = std::numeric_limits<double>::infinity();
    const auto n = static_cast<long>(e);
#pragma omp simd reduction(min : dt)
    for (auto a = static_cast<long>(b); a < n; ++a) {
      double acoustic, body;
      if constexpr (W388) {
        acoustic = courant * (h[a] / (sound[a] + signal[a]));  // W (3.88), (3.90)
        body = courant * std::sqrt(h[a] / norm(acc[a]));       // W (3.89), (3.90)
      } else {
        acoustic = courant * (h[a] / ((local ? sound[a] : c) + norm(v[a])));
        body = 0.25 * std::sqrt(h[a] / norm(acc[a]));
      }
      double viscous;
      if constexpr (Eddy)
        viscous = 0.125 * h[a] * h[a] * rho0 / (mu + rho0 * nu_t[a]);
      else
        viscous = 0.125 * h[a] * h[a] * rho0 / mu;
      dt = std::min(dt, std::min(std::min(acoustic, body), viscous));
    }
    return dt;
  }

  // BL (63)'s rule with one h and the reference c: dt_a falls as |v_a| and |a_a| grow, and
  // sqrt is monotone, so min_a dt_a is dt_a at the largest |v_a|^2 and |a_a|^2 (each term
  // rounded as least_of rounds it: the same bits). Two maxima per particle instead of three
  // square roots and three divisions (1.1 % of a `standard` step at 1e5, perf).
  double least_uniform(const ParticleSet<D>& ps, std::size_t b, std::size_t e, double h) const {
    if (b >= e) return std::numeric_limits<double>::infinity();
    const Vec<D>* __restrict v = ps.v.data();
    const Vec<D>* __restrict acc = ps.a.data();
    double v2 = 0.0, a2 = 0.0;
    const auto n = static_cast<long>(e);
#pragma omp simd reduction(max : v2, a2)
    for (auto a = static_cast<long>(b); a < n; ++a) {
      v2 = std::max(v2, norm2(v[a]));
      a2 = std::max(a2, norm2(acc[a]));
    }
    const double acoustic = cfl * (h / (c0 + std::sqrt(v2)));
    const double body = 0.25 * std::sqrt(h / std::sqrt(a2));
    const double viscous = 0.125 * h * h * rho0 / mu;
    return std::min(std::min(acoustic, body), viscous);
  }
};

// ps.signal of W (3.88) for the real particles: max_j |h_i u_ij . x_ij| / (|x_ij|^2 + eta^2),
// eta^2 = 0.01 h_i^2, over the neighbours within `range` (real and ghost, the ghosts' velocities
// those of the halo) with the velocities v of the state the step starts from.
template <int D>
void signal_speed_w388(const CellGrid<D>& grid, ParticleSet<D>& ps, double range) {
  neighbour_max(grid, ps, range, ps.signal, [&](std::size_t i, std::size_t j) {
    const Vec<D> xij = ps.x[i] - ps.x[j];
    const double hi = ps.h[i];
    return std::abs(hi * dot(ps.v[i] - ps.v[j], xij)) / (norm2(xij) + 0.01 * hi * hi);
  });
}

// min_a dt_a over the real particles. (A simulation takes it block by block in the force
// sweep's pass, sweep_least.)
template <int D>
double cfl_time_step(const ParticleSet<D>& ps, const Physics<D>& phys, double cfl) {
  const StepLimit<D> limit(phys, cfl);
  return limit.least(ps, 0, ps.n_real);
}

}  // namespace flume
