// Preset "continuity": continuity density BL (2)-(4) + force BL (20), variationally consistent
// (BL 2.4.2). Algorithm, one step (rho_a is the integrator's density at the integer time):
//   1. p_a = kappa((rho_a/rho0)^gamma - 1); refresh ghosts                BL (60)
//   2. sweep (if mu > 0 or LES): grad v_a, the stress    BL (22), common_steps.hpp
//   3. sweep: a_a = g + pressure force BL (20) + viscous BL (24) + artificial viscosity
//   -- leap-frog kick --
//   4. sweep: d rho_a/dt = -rho_a div v_a with v^{n+1/2}                   BL (2), (4)
#pragma once

#include "flume/equations/continuity_density_bl4.hpp"
#include "flume/equations/force_bonet_lok_20.hpp"
#include "flume/schemes/common_steps.hpp"
#include "flume/schemes/evolved_density_scheme.hpp"

namespace flume {

template <int D, class Kernel>
class ContinuityScheme final : public EvolvedDensityScheme<D, Kernel> {
 public:
  explicit ContinuityScheme(Physics<D> phys) : phys_(std::move(phys)) {}

  unsigned fields() const override { return kFieldDrho | stress_fields(phys_); }

  double compute_accelerations(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                               const StepLimit<D>& limit) const override {
    update_pressure(ps, phys_, halo);
    if (phys_.stress_term()) update_viscous_stress<D, Kernel>(ctx, ps, halo, phys_);
    ForceBonetLok20<D> pressure{ps};
    return accelerate<D, Kernel>(ctx, ps, phys_, limit, pressure);
  }

  void compute_state_rates(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                           std::vector<Vec<D>>& u) const override {
    halo.update_velocity(ps, u);
    ContinuityDensityBL4<D> continuity{ps, u};
    sweep<D, Kernel>(ctx, ps, "continuity", continuity);
  }

 private:
  Physics<D> phys_;
};

}  // namespace flume
