// Base of the schemes that integrate the density in time (continuity, CSPH): the kernel's
// support, and the Shepard density filter W (6.3) that the simulation applies every N steps.
#pragma once

#include "flume/schemes/common_steps.hpp"
#include "flume/schemes/scheme.hpp"

namespace flume {

template <int D, class Kernel>
class EvolvedDensityScheme : public Scheme<D> {
 public:
  double support() const final { return Kernel::support; }
  bool evolves_density() const final { return true; }
  void filter_density(ParticleSet<D>& ps, const SweepContext<D>& ctx,
                      const Halo<D>& halo) const final {
    shepard_filter<D, Kernel>(ctx, ps, halo);
  }
};

}  // namespace flume
