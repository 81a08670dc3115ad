// Schemes with the summation density BL (1):
//   preset "standard"     = BL (1) + force BL (7)  (variationally consistent, BL 2.4.1);
//   preset "inconsistent" = BL (1) + force BL (8) with "+" (= BL (20)): the mismatched pair of
//                           BL Fig 10 (antisymmetric, so it still keeps linear momentum).
// The density may be interpolated with a corrected kernel (Density): the Shepard correction
// BL (53) or the first-order correction BL (47)-(52); the force keeps its grad W.
// Algorithm, one step:
//   1. sweep: rho_a = sum_b m_b W_ab (or W~_ab)            BL (1), (53), (47)
//   2. p_a = kappa((rho_a/rho0)^gamma - 1) (in the same pass as the sweep's finish);
//      refresh ghosts                                       BL (60)
//   3. sweep (if mu > 0 or LES): grad v_a, the stress       BL (22), common_steps.hpp
//   4. sweep: a_a = g + pressure force + viscous + artificial viscosity
#pragma once

#include "flume/equations/density_summation.hpp"
#include "flume/equations/density_summation_first_order_bl47.hpp"
#include "flume/equations/density_summation_shepard_bl53.hpp"
#include "flume/schemes/common_steps.hpp"
#include "flume/schemes/scheme.hpp"

namespace flume {

template <int D, class Kernel, template <int> class Force,
          template <int> class Density = DensitySummation>
class SummationScheme final : public Scheme<D> {
 public:
  explicit SummationScheme(Physics<D> phys) : phys_(std::move(phys)) {}
  double support() const override { return Kernel::support; }
  bool evolves_density() const override { return false; }
  void xsph(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
            std::vector<Vec<D>>& u, double eps) const override {
    xsph_correction<D, Kernel>(ctx, ps, halo, u, eps);
  }
  unsigned fields() const override { return stress_fields(phys_); }

  double compute_accelerations(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                               const StepLimit<D>& limit) const override {
    Density<D> density{ps};
    // The equation of state in the same pass as the density's finish (sweep_then). A liquid's:
    // the summation schemes have no energy equation (the case reader pairs a gas with W's).
    const TaitEos tait = phys_.eos.tait();
    sweep_then<D, Kernel>(
        ctx, ps, "density",
        [&](std::size_t b, std::size_t e) {
          tait.pressure_and_sound_speed(ps.rho.data(), ps.p.data(), ps.c.data(), b, e);
        },
        density);
    halo.update_density(ps);
    halo.update_pressure(ps);

    if (phys_.stress_term()) update_viscous_stress<D, Kernel>(ctx, ps, halo, phys_);
    Force<D> pressure{ps};
    return accelerate<D, Kernel>(ctx, ps, phys_, limit, pressure);
  }

 private:
  Physics<D> phys_;
};

}  // namespace flume
