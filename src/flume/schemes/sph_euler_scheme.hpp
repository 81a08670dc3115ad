// Preset "sph-euler": SPH for the Euler equations, W 3.2, W (3.50)-(3.54):
//   d rho_i/dt = W (3.50)                       (density_rate_euler_w350.hpp)
//   d u_i/dt   = -sum_j m_j (p_j/rho_j^2 + p_i/rho_i^2 + Pi_ij/rho_bar^2) grad_i psi_ij  W (3.51)
//                (BL (7) + artificial viscosity W (3.18): the existing equations)
//   d e_i/dt   = W (3.52), for a gas            (energy_euler_w352.hpp)
//   d eps_i/dt = -(eps_i/(n rho_i)) d rho_i/dt  W (2.22) for (3.53) (erratum 5), if evolving
//   d x_i/dt   = u_i                            W (3.54)
// For a liquid (Tait) the energy equation is left out (the pressure depends on rho alone) and
// W (3.50) takes p_j/p_i = 1 (erratum 6). Algorithm, one evaluation of the rates:
//   1. p_i = p(rho_i, e_i), c_i; refresh ghosts
//   2. sweep (if mu > 0 or LES): grad v, the stress (common_steps.hpp; not in W's Euler equations)
//   3. sweep: a_i = g + W (3.51)
//   -- leap-frog kick (or the Runge-Kutta stage's velocity) --
//   4. sweep: d rho_i/dt, d e_i/dt with the velocity u of the integrator
#pragma once

#include "flume/equations/density_rate_euler_w350.hpp"
#include "flume/equations/energy_euler_w352.hpp"
#include "flume/equations/force_bonet_lok_7.hpp"
#include "flume/schemes/common_steps.hpp"
#include "flume/schemes/evolved_density_scheme.hpp"

namespace flume {

template <int D, class Kernel>
class SphEulerScheme final : public EvolvedDensityScheme<D, Kernel> {
 public:
  SphEulerScheme(Physics<D> phys, bool evolving_h)
      : phys_(std::move(phys)), evolving_h_(evolving_h) {}

  bool evolves_energy() const override { return phys_.eos.is_gas(); }
  bool evolves_smoothing_length() const override { return evolving_h_; }
  unsigned fields() const override {
    return kFieldDrho | (phys_.eos.is_gas() ? kFieldEnergy : 0u) |
           (evolving_h_ ? kFieldSmoothingRate : 0u) | stress_fields(phys_);
  }

  double compute_accelerations(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                               const StepLimit<D>& limit) const override {
    update_pressure(ps, phys_, halo);
    if (phys_.stress_term()) update_viscous_stress<D, Kernel>(ctx, ps, halo, phys_);
    ForceBonetLok7<D> pressure{ps};  // + Pi_ij / rho_bar^2, added by accelerate
    return accelerate<D, Kernel>(ctx, ps, phys_, limit, pressure);
  }

  void compute_state_rates(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                           std::vector<Vec<D>>& u) const override {
    halo.update_velocity(ps, u);
    const bool gas = phys_.eos.is_gas();
    DensityRateEulerW350<D> density{ps, u, gas};
    if (gas) {
      EnergyEulerW352<D> energy{ps, u, phys_.av_alpha, phys_.av_beta};
      sweep<D, Kernel>(ctx, ps, "continuity", density, energy);
    } else {
      sweep<D, Kernel>(ctx, ps, "continuity", density);
    }
  }

 private:
  Physics<D> phys_;
  bool evolving_h_;
};

}  // namespace flume
