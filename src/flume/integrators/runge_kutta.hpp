// The two Runge-Kutta steps of W 3.4, for dPhi_i/dt = F_i with Phi_i = (u_i, e_i, eps_i, x_i)
// W (3.84), and rho_i as well when the scheme evolves it (errata.md: W (3.84) omits it):
//
// midpoint, W (3.85)-(3.87):
//   Phi* = Phi^n + (dt/2) F^n,   Phi** = Phi^n + (dt/2) F*,   Phi^{n+1} = 2 Phi** - Phi^n;
// momentum-conserving modified RK, W (3.92), with dPhi/dt = F, dx/dt = U (W (3.91)):
//   Phi* = Phi^n + dt F^n,              x* = x^n + dt U^n,
//   Phi^{n+1/2} = (Phi* + Phi^n) / 2,   x^{n+1/2} = (x* + x^n) / 2,
//   Phi^{n+1} = Phi^n + dt F^{n+1/2},   x^{n+1} = x^n + (dt/2) (U* + U^n).
// Both take the rates twice a step: at the start (F^n) and at the stage state (F* or
// F^{n+1/2}), the simulation rebuilding the neighbours in between. Phi^n is kept in the
// particles' *_start fields (state fields: re-sorting by cell between the stages carries them).
// In the modified step the new velocity is u^n plus dt times forces whose pair terms cancel,
// so total linear momentum is kept to round-off; the midpoint step's 2 Phi** - Phi^n rounds
// twice. Neither keeps angular momentum exactly (methods.md).
// ps.v_half holds the velocity whose momentum the step keeps, v^{n+1}, for the diagnostics
// (and, inside a modified step, U* of W (3.92)).
// XSPH W (6.6) changes dx/dt = u to U = u + xsph(u) (xsph_w66.hpp): given the correction of the
// state's velocity (u^n at the start; at the stage u* of W (3.85)-(3.86), or W (3.92)'s U*
// with the stage's neighbours), the position updates use U. In the modified step
// x^{n+1} = x^n + (dt/2)(U* + U^n) is then taken as x^{n+1/2} + (dt/2) U*: the same sum, since
// x^{n+1/2} = x^n + (dt/2) U^n, without keeping U^n's correction.
#pragma once

#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/schemes/particle_passes.hpp"

namespace flume {

enum class RungeKuttaKind { midpoint, modified };

// Which scalar fields the scheme integrates besides x and u.
struct EvolvedFields {
  bool density = false;
  bool energy = false;
  bool smoothing_length = false;
};

template <int D>
class RungeKutta {
 public:
  RungeKutta(RungeKuttaKind kind, EvolvedFields evolved) : kind_(kind), evolved_(evolved) {}

  // The optional fields the step needs (ParticleSet::use_only).
  static unsigned fields() { return kFieldStepStart; }

  // From Phi^n with its rates F^n in ps to the stage state (Phi* of W (3.85), Phi^{n+1/2} of
  // W (3.92)), keeping Phi^n; after(b, e) follows each block as in LeapFrog::kick_and_drift.
  template <class After>
  long to_stage(ParticleSet<D>& ps, double dt, long none, const After& after,
                const std::vector<Vec<D>>* xsph = nullptr) const {
    return least_over_blocks(ps.n_real, none, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) {
        ps.x_start[i] = ps.x[i];
        ps.v_start[i] = ps.v[i];
        const Vec<D> drift = xsph ? ps.v_start[i] + (*xsph)[i] : ps.v_start[i];  // U^n
        if (kind_ == RungeKuttaKind::midpoint) {
          ps.x[i] = ps.x_start[i] + drift * (0.5 * dt);  // W (3.85)
          ps.v[i] = ps.v_start[i] + ps.a[i] * (0.5 * dt);
        } else {
          const Vec<D> x_star = ps.x_start[i] + drift * dt;  // W (3.92), first row
          const Vec<D> u_star = ps.v_start[i] + ps.a[i] * dt;
          ps.x[i] = (x_star + ps.x_start[i]) * 0.5;  // second row
          ps.v[i] = (u_star + ps.v_start[i]) * 0.5;
          ps.v_half[i] = u_star;  // U*, for x^{n+1}
        }
      }
      for_each_scalar(ps, [&](std::vector<double>& f, std::vector<double>& f_start,
                              const std::vector<double>& rate) {
        for (std::size_t i = b; i < e; ++i) {
          f_start[i] = f[i];
          f[i] = kind_ == RungeKuttaKind::midpoint ? f_start[i] + rate[i] * (0.5 * dt)
                                                   : (f_start[i] + rate[i] * dt + f_start[i]) * 0.5;
        }
      });
      return after(b, e);
    });
  }

  // From the stage state, with its rates (F* or F^{n+1/2}) in ps, to Phi^{n+1}.
  template <class After>
  long to_end(ParticleSet<D>& ps, double dt, long none, const After& after,
              const std::vector<Vec<D>>* xsph = nullptr) const {
    return least_over_blocks(ps.n_real, none, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) {
        if (kind_ == RungeKuttaKind::midpoint) {
          const Vec<D> drift = xsph ? ps.v[i] + (*xsph)[i] : ps.v[i];  // dx/dt = u* (+ XSPH)
          const Vec<D> x2 = ps.x_start[i] + drift * (0.5 * dt);        // W (3.86)
          const Vec<D> u2 = ps.v_start[i] + ps.a[i] * (0.5 * dt);
          ps.x[i] = x2 * 2.0 - ps.x_start[i];  // W (3.87)
          ps.v[i] = u2 * 2.0 - ps.v_start[i];
        } else if (xsph) {
          ps.x[i] = ps.x[i] + (ps.v_half[i] + (*xsph)[i]) * (0.5 * dt);  // W (3.92), see above
          ps.v[i] = ps.v_start[i] + ps.a[i] * dt;
        } else {
          ps.x[i] = ps.x_start[i] + (ps.v_half[i] + ps.v_start[i]) * (0.5 * dt);  // W (3.92)
          ps.v[i] = ps.v_start[i] + ps.a[i] * dt;
        }
        ps.v_half[i] = ps.v[i];
      }
      for_each_scalar(ps, [&](std::vector<double>& f, std::vector<double>& f_start,
                              const std::vector<double>& rate) {
        for (std::size_t i = b; i < e; ++i)
          f[i] = kind_ == RungeKuttaKind::midpoint
                     ? (f_start[i] + rate[i] * (0.5 * dt)) * 2.0 - f_start[i]
                     : f_start[i] + rate[i] * dt;
      });
      return after(b, e);
    });
  }

 private:
  // f(field, its Phi^n copy, its rate) for each evolved scalar.
  template <class F>
  void for_each_scalar(ParticleSet<D>& ps, F&& f) const {
    if (evolved_.density) f(ps.rho, ps.rho_start, ps.drho);
    if (evolved_.energy) f(ps.e, ps.e_start, ps.de);
    if (evolved_.smoothing_length) f(ps.h, ps.h_start, ps.dh);
  }

  RungeKuttaKind kind_;
  EvolvedFields evolved_;
};

}  // namespace flume
