// Base of the schemes that integrate the density in time (continuity, CSPH): the kernel's
// support, the density filter (W (6.3)'s Shepard average or its first-order form) that the
// simulation applies every N steps, and XSPH W (6.6).
#pragma once

#include "flume/schemes/common_steps.hpp"
#include "flume/schemes/scheme.hpp"

namespace flume {

template <int D, class Kernel>
class EvolvedDensityScheme : public Scheme<D> {
 public:
  double support() const final { return Kernel::support; }
  bool evolves_density() const final { return true; }
  void filter_density(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
                      DensityFilter filter) const final {
    if (filter == DensityFilter::first_order)
      first_order_filter<D, Kernel>(ctx, ps, halo);
    else
      shepard_filter<D, Kernel>(ctx, ps, halo);
  }
  void xsph(ParticleSet<D>& ps, const SweepContext<D>& ctx, const Halo<D>& halo,
            std::vector<Vec<D>>& u, double eps) const final {
    xsph_correction<D, Kernel>(ctx, ps, halo, u, eps);
  }
};

}  // namespace flume
