// Presets "wsph", "rsph" and "les-sph": weak SPH, W 3.3, W (3.79)-(3.83), weak renormalized
// SPH, W 4.1, W (4.19)-(4.23), the same equations with B_ij grad psi_ij for grad psi_ij, and
// LES-SPH, W 5.6, W (5.33)-(5.34): weak SPH with the Smagorinsky sub-grid stress:
//   d rho_i/dt = -sum_j (m_j rho_i p_j)/(rho_j p_i) (u_j - u_i) . G_ij   (3.79)/(4.19), sign
//                corrected (erratum 4)                             (density_rate_weak_w379.hpp)
//   d u_i/dt   = -sum_j m_j/(rho_i rho_j) (p_j + p_i + Pi_ij) G_ij   (3.80)/(4.20)
//                                                                  (force_weak_w380.hpp)
//                [+ sum_j m_j/(rho_i rho_j) (sigma_i - tau_i + sigma_j - tau_j) grad_i psi_ij,
//                 LES, (5.33) corrected (erratum 7)                (subgrid_stress_w531.hpp)]
//   d e_i/dt   = -sum_j m_j/(rho_i rho_j) (p_j + Pi_ij/2) (u_j - u_i) . G_ij, for a gas
//                (3.81)/(4.21)                                     (energy_weak_w381.hpp)
//   d eps_i/dt = -(eps_i/(n rho_i)) d rho_i/dt  (3.82)/(4.22) as corrected (erratum 5), if evolving
//   d x_i/dt   = u_i                            (3.83)/(4.23)
// with G_ij = grad_i psi_ij (wsph, les-sph) or B_ij grad_i psi_ij, B_ij = (B_i + B_j)/2 W (4.16)
// (rsph; kernel_gradient_w416.hpp). For a liquid (Tait) the energy equation is left out and
// p_j/p_i = 1 in the density rate (erratum 6); LES-SPH is W's model of water, a liquid only
// (its energy equation (5.34) is not needed). Algorithm, one evaluation of the rates:
//   1. (rsph) sweep: B_i = E_i^{-1}, W (4.8)-(4.11) (= BL (45)'s L_i); refresh ghosts
//   2. p_i = p(rho_i, e_i), c_i; refresh ghosts
//   3. sweep (if mu > 0 or LES): grad v, the stresses sigma and -tau (common_steps.hpp)
//   4. sweep: a_i = g + W (3.80) / (4.20) (its Pi_ij included) + the stress terms
//   -- leap-frog kick (or the Runge-Kutta stage's velocity) --
//   5. sweep: d rho_i/dt, d e_i/dt with the velocity u of the integrator (B_i of step 1)
#pragma once

#include "flume/equations/corrected_velocity_gradient.hpp"
#include "flume/equations/density_rate_weak_w379.hpp"
#include "flume/equations/energy_weak_w381.hpp"
#include "flume/equations/force_weak_w380.hpp"
#include "flume/equations/kernel_gradient_w416.hpp"
#include "flume/schemes/common_steps.hpp"
#include "flume/schemes/evolved_density_scheme.hpp"

namespace flume {

template <int D, class Kernel, class Gradient>
class WeakSphScheme final : public EvolvedDensityScheme<D, Kernel> {
 public:
  WeakSphScheme(Physics<D> phys, bool evolving_h)
      : phys_(std::move(phys)), evolving_h_(evolving_h) {}

  bool evolves_energy() const override { return phys_.eos.is_gas(); }
  bool evolves_smoothing_length() const override { return evolving_h_; }
  unsigned fields() const override {
    return kFieldDrho | (phys_.eos.is_gas() ? kFieldEnergy : 0u) |
           (evolving_h_ ? kFieldSmoothingRate : 0u) | (Gradient::kRenormalized ? kFieldL : 0u) |
           stress_fields(phys_);
  }

  double compute_accelerations(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                               const StepLimit<D>& limit) const override {
    if constexpr (Gradient::kRenormalized) {
      // B_i = L_i; no velocity gradient (the stress terms take BL (22)'s, update_viscous_stress).
      CorrectedVelocityGradient<D, Correction::gradient, false> renormalization{ps};
      sweep<D, Kernel>(ctx, ps, "correction", renormalization);
      halo.update_corrections(ps);
    }
    update_pressure(ps, phys_, halo);
    if (phys_.stress_term()) update_viscous_stress<D, Kernel>(ctx, ps, halo, phys_);
    Physics<D> without_av = phys_;  // Pi_ij is inside W (3.80)'s bracket
    without_av.av_alpha = without_av.av_beta = 0.0;
    ForceWeakW380<D, Gradient> force{ps, phys_.av_alpha, phys_.av_beta};
    return accelerate<D, Kernel>(ctx, ps, without_av, limit, force);
  }

  void compute_state_rates(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                           std::vector<Vec<D>>& u) const override {
    halo.update_velocity(ps, u);
    const bool gas = phys_.eos.is_gas();
    DensityRateWeakW379<D, Gradient> density{ps, u, gas};
    if (gas) {
      EnergyWeakW381<D, Gradient> energy{ps, u, phys_.av_alpha, phys_.av_beta};
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
