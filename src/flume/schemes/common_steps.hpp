// Steps shared by the schemes: the equation of state, the viscous stress through the velocity
// gradient, the force sweep that sums the body force, a pressure force and the viscosities, and
// the Shepard density filter.
#pragma once

#include <algorithm>
#include <type_traits>
#include <vector>

#include "flume/boundaries/halo.hpp"
#include "flume/equations/acceleration_sum.hpp"
#include "flume/equations/shepard_filter_w63.hpp"
#include "flume/equations/velocity_gradient_bl22.hpp"
#include "flume/equations/viscosity_artificial_monaghan.hpp"
#include "flume/equations/viscosity_bonet_lok_24.hpp"
#include "flume/integrators/time_step.hpp"
#include "flume/schemes/physics.hpp"
#include "flume/schemes/sweep.hpp"

namespace flume {

// p and c for the real particles, then copied to the ghosts: Tait p(rho_a), BL (60), or the
// ideal gas p(rho_a, e_a); c_a the local sound speed. One loop per equation of state, each
// without a branch, so that it vectorises.
template <int D>
void update_pressure(ParticleSet<D>& ps, const Physics<D>& phys, const Halo<D>& halo) {
  if (phys.eos.is_gas()) {
    const IdealGasEos gas = phys.eos.gas();
    for_each_real(ps.n_real, [&](std::size_t i) {
      ps.p[i] = gas.pressure(ps.rho[i], ps.e[i]);
      ps.c[i] = gas.sound_speed(ps.rho[i], ps.p[i]);
    });
  } else {
    const TaitEos tait = phys.eos.tait();
    for_each_real(ps.n_real, [&](std::size_t i) {
      ps.p[i] = tait.pressure(ps.rho[i]);
      ps.c[i] = tait.sound_speed(ps.rho[i], ps.p[i]);
    });
  }
  halo.update_scalar(ps, ps.p);
  halo.update_scalar(ps, ps.c);
}

// Sweep: rho_a <- Shepard average of the densities, W (6.3), then copied to the ghosts. The
// mirror ghosts take part (W does not say, errata.md): a particle at a wall then averages over a
// full kernel, as in the interior.
template <int D, class Kernel>
void shepard_filter(const SweepContext<D>& ctx, ParticleSet<D>& ps, const Halo<D>& halo) {
  // The slot past the sweep's one accumulator (sweep.hpp, kFirstAccSlot).
  auto& filtered = ctx.work.template buffer<double>(detail::kFirstAccSlot + 1, ps.n_real);
  ShepardFilterW63<D> filter{ps, filtered};
  sweep<D, Kernel>(ctx, ps, "shepard_filter", filter);
  std::copy(filtered.begin(), filtered.end(), ps.rho.begin());
  halo.update_scalar(ps, ps.rho);
}

// Sweep: grad v_a, BL (22); then sigma'_a = 2 mu d'_a for real and ghost particles, BL (23)-(24).
template <int D, class Kernel>
void update_viscous_stress(const SweepContext<D>& ctx, ParticleSet<D>& ps, const Halo<D>& halo,
                           double mu) {
  VelocityGradientBL22<D> gradient{ps};
  sweep<D, Kernel>(ctx, ps, "velocity_gradient", gradient);
  halo.update_velocity_gradient(ps);
  update_deviatoric_stress(ps, mu);
}

// Sweep: a_a = g + the equations given (a pressure force, ...) + physical viscosity BL (24)
// (when mu > 0, from ps.stress) + artificial viscosity W (3.18) (when alpha or beta > 0). The
// terms that are off are left out of the sweep, not evaluated as zeros; the terms on share one
// accumulator (AccelerationSum). Returns the stable time step min_a dt_a (time_step.hpp), taken
// as each a_a is finished: no pass of its own over the particles.
template <int D, class Kernel, class... Forces>
double accelerate(const SweepContext<D>& ctx, ParticleSet<D>& ps, const Physics<D>& phys,
                  const StepLimit<D>& limit, Forces&... forces) {
  ViscosityBonetLok24<D> viscous{ps};
  ViscosityArtificialMonaghan<D> artificial{ps, phys.av_alpha, phys.av_beta};
  const bool av = phys.av_alpha != 0.0 || phys.av_beta != 0.0;
  auto run = [&](const auto&... terms) {
    AccelerationSum<D, std::remove_cvref_t<decltype(terms)>...> sum{ps, phys.gravity, terms...};
    return sweep_least<D, Kernel>(
        ctx, ps, "force", [&](std::size_t b, std::size_t e) { return limit.least(ps, b, e); }, sum);
  };
  if (phys.mu > 0.0 && av) return run(forces..., viscous, artificial);
  if (phys.mu > 0.0) return run(forces..., viscous);
  if (av) return run(forces..., artificial);
  return run(forces...);
}

}  // namespace flume
