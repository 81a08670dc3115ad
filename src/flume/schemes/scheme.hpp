// A scheme turns the particle state into rates: accelerations and, when it evolves density,
// density rates. It is an ordered list of groups (fused neighbour sweeps) with the ghost
// refreshes between them; its concrete files read like the algorithm in the paper.
#pragma once

#include <memory>
#include <string>

#include "flume/boundaries/halo.hpp"
#include "flume/core/particle_set.hpp"
#include "flume/integrators/time_step.hpp"
#include "flume/schemes/physics.hpp"
#include "flume/schemes/sweep.hpp"

namespace flume {

// Which average the density filter takes (Scheme::filter_density): W (6.3)'s Shepard average,
// or the same interpolation with BL (47)-(52)'s first-order corrected kernel, which also keeps a
// linear density (a hydrostatic column) at a free surface.
enum class DensityFilter { shepard, first_order };

template <int D>
class Scheme {
 public:
  virtual ~Scheme() = default;
  // Kernel support radius in units of h (2 for the cubic spline, 3 for the quintic...).
  virtual double support() const = 0;
  // True when rho is integrated in time (continuity); false when it is recomputed (summation).
  virtual bool evolves_density() const = 0;
  // True when the specific internal energy e is integrated in time (a gas, W (3.52), (3.81)).
  virtual bool evolves_energy() const { return false; }
  // True when the smoothing length evolves with the density, W (2.22).
  virtual bool evolves_smoothing_length() const { return false; }
  // The optional particle fields (OptionalField bits) the scheme reads or writes.
  virtual unsigned fields() const = 0;
  // Fills ps.a of the real particles (and ps.rho, for a summation density) and returns the
  // stable time step of the new state, limit.least over the real particles (time_step.hpp). The
  // ghosts are appended to ps, sorted into ctx.grid with the real particles; halo refreshes the
  // ghosts between groups.
  virtual double compute_accelerations(ParticleSet<D>& ps, const SweepContext<D>& ctx,
                                       const Halo<D>& halo, const StepLimit<D>& limit) const = 0;
  // For schemes that evolve density (energy, smoothing length): fills ps.drho (ps.de, ps.dh)
  // from the positions x and the velocity field u: leap-frog's v^{n+1/2} after the kick
  // (leapfrog.hpp says why), a Runge-Kutta stage's v. The ghosts' u is refreshed here.
  virtual void compute_state_rates(ParticleSet<D>& /*ps*/, const SweepContext<D>& /*ctx*/,
                                   const Halo<D>& /*halo*/, std::vector<Vec<D>>& /*u*/) const {}
  // For schemes that evolve density: the density filter over the real particles (W (6.3)'s
  // Shepard average, or its first-order form), ghosts appended and refreshed. (A summation
  // density is recomputed every step, so the case reader does not allow the filter with it.)
  virtual void filter_density(ParticleSet<D>& /*ps*/, const SweepContext<D>& /*ctx*/,
                              const Halo<D>& /*halo*/, DensityFilter /*filter*/) const {}
  // XSPH W (6.6): ps.xsph, the drift correction of the velocity field u (ghosts refreshed here;
  // common_steps.hpp, xsph_correction).
  virtual void xsph(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                    std::vector<Vec<D>>& u, double eps) const = 0;
};

}  // namespace flume
