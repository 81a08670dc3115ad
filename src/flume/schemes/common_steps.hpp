// Steps shared by the schemes: the equation of state, the viscous and sub-grid stress through
// the velocity gradient, the force sweep that sums the body force, a pressure force and the
// viscosities, the Shepard density filter and XSPH.
#pragma once

#include <algorithm>
#include <type_traits>
#include <vector>

#include "flume/boundaries/halo.hpp"
#include "flume/equations/acceleration_sum.hpp"
#include "flume/equations/density_summation_first_order_bl47.hpp"
#include "flume/equations/shepard_filter_w63.hpp"
#include "flume/equations/subgrid_stress_w531.hpp"
#include "flume/equations/velocity_gradient_bl22.hpp"
#include "flume/equations/viscosity_artificial_monaghan.hpp"
#include "flume/equations/viscosity_bonet_lok_24.hpp"
#include "flume/equations/viscosity_morris_w57.hpp"
#include "flume/equations/viscous_stress_w511.hpp"
#include "flume/equations/xsph_w66.hpp"
#include "flume/integrators/time_step.hpp"
#include "flume/schemes/physics.hpp"
#include "flume/schemes/sweep.hpp"

namespace flume {

// p and c for the real particles, then copied to the ghosts (hydrostatic ghosts add the
// column across the wall, halo.hpp): Tait p(rho_a), BL (60), or the ideal gas p(rho_a, e_a);
// c_a the local sound speed. One loop per equation of state, each
// without a branch, so that it vectorises (the liquid's in blocks: TaitEos takes its test on
// gamma once a block).
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
    for_each_block(ps.n_real, [&](std::size_t b, std::size_t e) {
      tait.pressure_and_sound_speed(ps.rho.data(), ps.p.data(), ps.c.data(), b, e);
    });
  }
  halo.update_pressure(ps);
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
  halo.update_density(ps);
}

// Sweep: rho_a <- the density interpolated with BL (47)-(52)'s first-order corrected kernel,
// rho_a = sum_b m_b W~_b(x_a), the filter W (6.3) with W~ in place of the Shepard kernel BL (53)
// that W (6.3) is. Where W (6.3) reads a hydrostatic column's free-surface particles high (their
// kernels hold only denser water below), this reproduces the column's linear density, so
// filtering does not push a pressure onto the surface. The equation writes ps.rho in its
// finish: the volumes it reads were all taken before the pairs (own.hpp).
template <int D, class Kernel>
void first_order_filter(const SweepContext<D>& ctx, ParticleSet<D>& ps, const Halo<D>& halo) {
  DensitySummationFirstOrderBL47<D> filter{ps};
  sweep<D, Kernel>(ctx, ps, "first_order_filter", filter);
  halo.update_density(ps);
}

// The stress of BL (24)'s pair form for every particle, ghosts included, from ps.grad_v (once
// per step, not per pair): the viscous stress, 2 mu d' of BL (23)-(24) or W (5.11)'s (none with
// Morris's W (5.7), a pair term of its own), plus LES's -tau of W (5.31)-(5.32) and its eddy
// viscosity nu_t (for the time step).
template <int D>
void update_stress(ParticleSet<D>& ps, const Physics<D>& phys) {
  if (!phys.les.on && phys.viscous == ViscousTerm::bl24) {
    update_deviatoric_stress(ps, phys.mu);
    return;
  }
  const bool viscous = phys.mu > 0.0 && phys.viscous != ViscousTerm::w57;
  const auto n = static_cast<long>(ps.size());
#pragma omp parallel for schedule(static)
  for (long ii = 0; ii < n; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    Mat<D> s{};
    if (viscous)
      s = phys.viscous == ViscousTerm::w511 ? navier_stokes_stress_w511(ps.grad_v[i], phys.mu)
                                            : deviatoric_stress(ps.grad_v[i], phys.mu);
    if (phys.les.on) {
      const SubgridStress<D> sgs = subgrid_stress_w531(ps.grad_v[i], ps.rho[i], phys.les);
      s += sgs.minus_tau;
      ps.nu_t[i] = sgs.nu_r;
    }
    ps.stress[i] = s;
  }
}

// Sweep: grad v_a, BL (22) (= W (5.5) with omega_j = m_j / rho_j); then the stress of every
// particle (update_stress).
template <int D, class Kernel>
void update_viscous_stress(const SweepContext<D>& ctx, ParticleSet<D>& ps, const Halo<D>& halo,
                           const Physics<D>& phys) {
  VelocityGradientBL22<D> gradient{ps};
  sweep<D, Kernel>(ctx, ps, "velocity_gradient", gradient);
  halo.update_velocity_gradient(ps);
  update_stress(ps, phys);
}

// The optional fields of the stress terms (Physics::stress_term).
template <int D>
unsigned stress_fields(const Physics<D>& phys) {
  return phys.stress_term() ? kFieldGradV | kFieldStress | (phys.les.on ? kFieldEddy : 0u) : 0u;
}

// Sweep: ps.xsph = XSPH's drift correction W (6.6) of the velocity field u (its ghosts
// refreshed here).
template <int D, class Kernel>
void xsph_correction(const SweepContext<D>& ctx, ParticleSet<D>& ps, const Halo<D>& halo,
                     std::vector<Vec<D>>& u, double eps) {
  halo.update_velocity(ps, u);
  XsphW66<D> xsph{ps, u, eps};
  sweep<D, Kernel>(ctx, ps, "xsph", xsph);
}

// Sweep: a_a = g + the equations given (a pressure force, ...) + the stress term of BL (24)'s
// pair form (physical viscosity BL (24) or W (5.11), LES's sub-grid stress; from ps.stress) +
// Morris's viscosity W (5.7) + artificial viscosity W (3.18) (when alpha or beta > 0). The
// terms that are off are left out of the sweep, not evaluated as zeros (but with Morris's term,
// the artificial viscosity stays in, zero when alpha = beta = 0: two sweeps fewer to compile);
// the terms on share one accumulator (AccelerationSum). Returns the stable time step
// min_a dt_a (time_step.hpp), taken as each a_a is finished: no pass of its own over the
// particles.
template <int D, class Kernel, class... Forces>
double accelerate(const SweepContext<D>& ctx, ParticleSet<D>& ps, const Physics<D>& phys,
                  const StepLimit<D>& limit, Forces&... forces) {
  ViscosityBonetLok24<D> viscous{ps};
  ViscosityArtificialMonaghan<D> artificial{ps, phys.av_alpha, phys.av_beta};
  ViscosityMorrisW57<D> morris{ps, phys.mu};
  const bool av = phys.av_alpha != 0.0 || phys.av_beta != 0.0;
  const bool stress = phys.stress_term();
  auto run = [&](const auto&... terms) {
    AccelerationSum<D, std::remove_cvref_t<decltype(terms)>...> sum{ps, phys.gravity, terms...};
    return sweep_least<D, Kernel>(
        ctx, ps, "force",
        [&](std::size_t b, std::size_t e) { return limit.least(ps, b, e, ctx.uniform_h); }, sum);
  };
  if (phys.morris_term()) {
    if (stress) return run(forces..., viscous, morris, artificial);
    return run(forces..., morris, artificial);
  }
  if (stress && av) return run(forces..., viscous, artificial);
  if (stress) return run(forces..., viscous);
  if (av) return run(forces..., artificial);
  return run(forces...);
}

}  // namespace flume
