// Continuity schemes with a correction of BL section 4 (correction.hpp): the density follows the
// continuity equation with the corrected divergence, and the force is the variational partner
// of the corrected velocity gradient.
//   mixed    (preset "csph", BL 4.3): gradient BL (55), force BL (59);
//   shepard  (BL (53), (57)):         gradient BL (55) with L = I, force BL (59) with L = I;
//   gradient (BL 4.1):                gradient BL (43), force of methods.md erratum 9.
// For mixed and shepard, sum_b V_b grad W~_b(x_a) = 0 (BL (57), erratum 2), so erratum 9's
// sigma_a term vanishes and the force is BL (59)'s; for the gradient correction it does not.
// Algorithm, one step:
//   1. sweep: S_a, gamma_a, L_a, grad v_a (if viscous)      BL (53), (57), (43)/(55), (45)/(58)
//   2. p_a = kappa((rho_a/rho0)^gamma - 1); refresh ghosts   BL (60)
//   3. sweep: a_a = g + internal force                       BL (59) / erratum 9
//   -- leap-frog kick --
//   4. sweep: d rho_a/dt = -rho_a tr(grad v_a) with v^{n+1/2}, L_a from step 1   BL (2), (43)/(55)
// Artificial viscosity W (3.18) may be added (alpha, beta); BL's CSPH runs use none.
#pragma once

#include "flume/equations/corrected_velocity_gradient.hpp"
#include "flume/equations/force_csph_bl59.hpp"
#include "flume/equations/force_gradient_corrected.hpp"
#include "flume/equations/viscosity_artificial_monaghan.hpp"
#include "flume/schemes/common_steps.hpp"
#include "flume/schemes/evolved_density_scheme.hpp"

namespace flume {

template <int D, class Kernel, Correction C>
class CorrectedContinuityScheme final : public EvolvedDensityScheme<D, Kernel> {
 public:
  explicit CorrectedContinuityScheme(Physics<D> phys) : phys_(std::move(phys)) {}

  unsigned fields() const override {
    return kFieldDrho | kFieldL | (corrects_kernel(C) ? kFieldShepard : 0u) |
           (phys_.mu > 0.0 ? kFieldGradV | kFieldStress : 0u);
  }

  double compute_accelerations(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                               const StepLimit<D>& limit) const override {
    // The velocity gradient only where the set carries it (fields(): for the viscous stress);
    // inviscid, the sweep carries 8 sums a particle instead of 15 in 2D.
    const bool velocity = ps.uses(kFieldGradV);
    if (velocity) {
      CorrectedVelocityGradient<D, C, true> correction{ps};
      sweep<D, Kernel>(ctx, ps, "correction", correction);
    } else {
      CorrectedVelocityGradient<D, C, false> correction{ps};
      sweep<D, Kernel>(ctx, ps, "correction", correction);
    }
    if constexpr (corrects_kernel(C)) halo.update_shepard(ps);
    halo.update_corrections(ps);
    if (velocity) halo.update_velocity_gradient(ps);
    if (phys_.mu > 0.0) update_deviatoric_stress(ps, phys_.mu);
    update_pressure(ps, phys_, halo);

    Physics<D> inviscid = phys_;  // the viscous stress is part of the force's sigma
    inviscid.mu = 0.0;
    if constexpr (corrects_kernel(C)) {
      ForceCsphBL59<D> internal{ps, phys_.mu};
      return accelerate<D, Kernel>(ctx, ps, inviscid, limit, internal);
    } else {
      ForceGradientCorrected<D> internal{ps, phys_.mu};
      return accelerate<D, Kernel>(ctx, ps, inviscid, limit, internal);
    }
  }

  void compute_state_rates(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                           std::vector<Vec<D>>& u) const override {
    halo.update_velocity(ps, u);
    CorrectedContinuity<D, C> continuity{ps, u};
    sweep<D, Kernel>(ctx, ps, "continuity", continuity);
  }

 private:
  Physics<D> phys_;
};

}  // namespace flume
