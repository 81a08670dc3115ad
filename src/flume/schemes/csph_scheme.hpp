// Preset "csph": mixed kernel and gradient correction, BL section 4.3. The density follows the
// continuity equation with the corrected divergence, and the force BL (59) is the variational
// partner of the corrected velocity gradient BL (55). Algorithm, one step:
//   1. sweep: S_a, gamma_a, L_a, grad v_a                   BL (53), (57), (55), (58)
//   2. p_a = kappa((rho_a/rho0)^gamma - 1); refresh ghosts   BL (60)
//   3. sweep: a_a = g + internal force                       BL (59)
//   -- leap-frog kick --
//   4. sweep: d rho_a/dt = -rho_a tr(grad v_a) with v^{n+1/2}, L_a from step 1   BL (2), (55)
// Artificial viscosity W (3.18) may be added (alpha, beta); BL's CSPH runs use none.
#pragma once

#include "flume/equations/csph_gradient_bl58.hpp"
#include "flume/equations/force_csph_bl59.hpp"
#include "flume/equations/viscosity_artificial_monaghan.hpp"
#include "flume/schemes/common_steps.hpp"
#include "flume/schemes/evolved_density_scheme.hpp"

namespace flume {

template <int D, class Kernel>
class CsphScheme final : public EvolvedDensityScheme<D, Kernel> {
 public:
  explicit CsphScheme(Physics<D> phys) : phys_(std::move(phys)) {}

  unsigned fields() const override {
    return kFieldDrho | kFieldGradV | kFieldShepard | kFieldL |
           (phys_.mu > 0.0 ? kFieldStress : 0u);
  }

  void compute_accelerations(ParticleSet<D>& ps, const SweepContext<D>& ctx,
                             const Halo<D>& halo) const override {
    CsphGradientBL58<D> correction{ps};
    sweep<D, Kernel>(ctx, ps, "correction", correction);
    halo.update_shepard(ps);
    halo.update_corrections(ps);
    halo.update_velocity_gradient(ps);
    if (phys_.mu > 0.0) update_deviatoric_stress(ps, phys_.mu);
    update_pressure(ps, phys_, halo);

    ForceCsphBL59<D> internal{ps, phys_.mu};
    Physics<D> inviscid = phys_;  // the viscous stress is part of BL (59)'s sigma
    inviscid.mu = 0.0;
    accelerate<D, Kernel>(ctx, ps, inviscid, internal);
  }

  void compute_density_rate(ParticleSet<D>& ps, const SweepContext<D>& ctx,
                            const Halo<D>& halo) const override {
    halo.update_velocity(ps, ps.v_half);
    CsphContinuity<D> continuity{ps, ps.v_half};
    sweep<D, Kernel>(ctx, ps, "continuity", continuity);
  }

 private:
  Physics<D> phys_;
};

}  // namespace flume
