// Leap-frog, BL (61)-(62), with the variable step of errata.md:
//   v^{n+1/2} = v^{n-1/2} + dt_bar a^n,   dt_bar = (dt^n + dt^{n+1}) / 2,        (kick)
//   x^{n+1}   = x^n + dt^{n+1} v^{n+1/2}.                                        (drift)
// The first step has dt^0 = 0, so v^{1/2} = v^0 + (dt/2) a^0.
// BL does not say how the density is advanced. flume keeps rho with x at integer levels and
// advances it with the velocity of the kick,
//   rho^{n+1} = rho^n + dt^{n+1} (d rho/dt)(x^n, v^{n+1/2}),
// and likewise a gas's internal energy e and an evolving smoothing length (W (2.22)),
// the symplectic-Euler pairing of the acoustic (rho, v) system: stable for dt below the CFL
// limit. (Advancing rho alongside v from rates at the integer time, with v and rho predicted
// there, is the forward-Euler pairing and lets still water drift into a growing acoustic mode.)
// The velocity-dependent terms of a^n (viscosity) use the prediction v^n = v^{n-1/2} +
// (dt^n/2) a^{n-1}. Forces depend on positions only through x^n, so sum m x^{n+1} x v^{n+1/2} is
// kept exactly by central forces (BL 3.3.1): the staggered angular momentum of the diagnostics.
#pragma once

#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/integrators/runge_kutta.hpp"
#include "flume/schemes/particle_passes.hpp"

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

  // kick then drift in one pass over the particles (the same operations on each particle in
  // the same order, so the same bits): for schemes whose density does not need the kick's
  // velocity in between. The particles go in blocks (least_over_blocks), and after(b, e)
  // follows the drift of each block [b, e) (the walls' put-back and the checks, while the
  // block is in cache: a pass of their own would read and write the state again); returns the
  // least value after returns, or `none`.
  template <class After>
  long kick_and_drift(ParticleSet<D>& ps, double dt, long none, const After& after) {
    const double dt_bar = 0.5 * (dt_prev_ + dt);
    dt_prev_ = dt;
    return least_over_blocks(ps.n_real, none, [&](std::size_t b, std::size_t e) {
      // Component by component: the vectors' D doubles side by side, one flat loop that the
      // compiler vectorises (a loop over the Vec<D> did not).
      double* __restrict x = components(ps.x);
      double* __restrict v = components(ps.v);
      double* __restrict v_half = components(ps.v_half);
      const double* __restrict a = components(ps.a);
      const double kick = dt_bar, step = dt;
#pragma omp simd
      for (std::size_t c = b * D; c < e * D; ++c) {
        v_half[c] += a[c] * kick;
        x[c] += v_half[c] * step;
        v[c] = v_half[c] + a[c] * (0.5 * step);
      }
      return after(b, e);
    });
  }
  // rho^{n+1} = rho^n + dt drho (drho evaluated after the kick; e and h likewise when they
  // evolve), then the drift BL (62): x^{n+1} = x^n + dt v^{n+1/2}, and the prediction
  // v^{n+1} = v^{n+1/2} + (dt/2) a^n used by the velocity-dependent terms of the next step and
  // by the kinetic energy; then after(b, e), as kick_and_drift. With XSPH W (6.6) the drift
  // velocity is v^{n+1/2} + xsph (the correction of v^{n+1/2}, xsph_w66.hpp).
  template <class After>
  long advance_state_and_drift(ParticleSet<D>& ps, double dt, EvolvedFields evolved, long none,
                               const After& after,
                               const std::vector<Vec<D>>* xsph = nullptr) const {
    return least_over_blocks(ps.n_real, none, [&](std::size_t b, std::size_t e) {
      const double step = dt;
      const auto advance = [&](std::vector<double>& field, const std::vector<double>& rate) {
        double* __restrict f = field.data();
        const double* __restrict df = rate.data();
#pragma omp simd
        for (std::size_t i = b; i < e; ++i)
          f[i] += step * df[i];
      };
      if (evolved.density) advance(ps.rho, ps.drho);
      if (evolved.energy) advance(ps.e, ps.de);
      if (evolved.smoothing_length) advance(ps.h, ps.dh);
      double* __restrict x = components(ps.x);  // component by component, as kick_and_drift
      double* __restrict v = components(ps.v);
      const double* __restrict v_half = components(ps.v_half);
      const double* __restrict a = components(ps.a);
      if (xsph) {
        const double* __restrict dx = components(*xsph);
#pragma omp simd
        for (std::size_t c = b * D; c < e * D; ++c) {
          x[c] += (v_half[c] + dx[c]) * step;
          v[c] = v_half[c] + a[c] * (0.5 * step);
        }
        return after(b, e);
      }
#pragma omp simd
      for (std::size_t c = b * D; c < e * D; ++c) {
        x[c] += v_half[c] * step;
        v[c] = v_half[c] + a[c] * (0.5 * step);
      }
      return after(b, e);
    });
  }

  // One whole step with the rates already in ps (a, and drho when evolve_density).
  void advance(ParticleSet<D>& ps, double dt, bool evolve_density) {
    auto nothing = [](std::size_t, std::size_t) { return 0L; };
    if (!evolve_density) {
      kick_and_drift(ps, dt, 0, nothing);
      return;
    }
    kick(ps, dt);
    advance_state_and_drift(ps, dt, EvolvedFields{true, false, false}, 0, nothing);
  }

 private:
  // The D components of every vector of a field, side by side (Vec<D> is D doubles).
  static_assert(sizeof(Vec<D>) == D * sizeof(double));
  static double* components(std::vector<Vec<D>>& f) {
    return f.data()->c.data();
  }
  static const double* components(const std::vector<Vec<D>>& f) {
    return f.data()->c.data();
  }

  // dt^n, the step before the one about to be taken (what a checkpoint keeps).
 public:
  double history() const {
    return dt_prev_;
  }
  void set_history(double dt_prev) {
    dt_prev_ = dt_prev;
  }

 private:
  double dt_prev_ = 0.0;
};

}  // namespace flume
