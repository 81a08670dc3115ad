// The body of make_kernel_scheme, included by the one translation unit of each kernel.
#pragma once

#include "flume/equations/force_bonet_lok_20.hpp"
#include "flume/equations/force_bonet_lok_7.hpp"
#include "flume/schemes/continuity_scheme.hpp"
#include "flume/schemes/corrected_continuity_scheme.hpp"
#include "flume/schemes/kernel_schemes.hpp"
#include "flume/schemes/sph_euler_scheme.hpp"
#include "flume/schemes/summation_scheme.hpp"
#include "flume/schemes/weak_sph_scheme.hpp"

namespace flume {

// A summation scheme with force F and the density's kernel correction.
template <int D, class K, template <int> class F>
std::unique_ptr<Scheme<D>> summation_scheme(const std::string& correction, const Physics<D>& phys) {
  if (correction == "none") return std::make_unique<SummationScheme<D, K, F>>(phys);
  if (correction == "shepard")
    return std::make_unique<SummationScheme<D, K, F, DensitySummationShepardBL53>>(phys);
  if (correction == "first_order")
    return std::make_unique<SummationScheme<D, K, F, DensitySummationFirstOrderBL47>>(phys);
  return nullptr;
}

template <int D, class K>
std::unique_ptr<Scheme<D>> make_kernel_scheme(const SchemeRows& rows, const Physics<D>& phys) {
  const std::string& c = rows.correction;
  if (rows.density == "summation" && rows.force == "bl7")
    return summation_scheme<D, K, ForceBonetLok7>(c, phys);
  if (rows.density == "summation" && rows.force == "bl20")
    return summation_scheme<D, K, ForceBonetLok20>(c, phys);
  if (rows.density == "continuity" && rows.force == "bl20") {
    if (c == "none") return std::make_unique<ContinuityScheme<D, K>>(phys);
    if (c == "gradient")
      return std::make_unique<CorrectedContinuityScheme<D, K, Correction::gradient>>(phys);
    if (c == "shepard")
      return std::make_unique<CorrectedContinuityScheme<D, K, Correction::shepard>>(phys);
  }
  // BL (59) is BL (20)'s variational form under the mixed correction
  // (corrected_continuity_scheme.hpp).
  if (rows.density == "continuity" && (rows.force == "bl59" || rows.force == "bl20") &&
      c == "mixed")
    return std::make_unique<CorrectedContinuityScheme<D, K, Correction::mixed>>(phys);
  // The thesis's schemes (W 3.2, 3.3, 4.1).
  const bool evolving_h = rows.smoothing_length == "evolving";
  if (rows.density == "w350" && rows.force == "w351" && c == "none")
    return std::make_unique<SphEulerScheme<D, K>>(phys, evolving_h);
  if (rows.density == "w379" && rows.force == "w380" && c == "none")
    return std::make_unique<WeakSphScheme<D, K, PlainGradient>>(phys, evolving_h);
  if (rows.density == "w379" && rows.force == "w380" && c == "renormalized")
    return std::make_unique<WeakSphScheme<D, K, RenormalizedGradient>>(phys, evolving_h);
  return nullptr;
}

}  // namespace flume

// Instantiates make_kernel_scheme for kernel template KERNEL in 2D and 3D.
#define FLUME_KERNEL_SCHEMES(KERNEL)                                                  \
  template std::unique_ptr<flume::Scheme<2>> flume::make_kernel_scheme<2, KERNEL<2>>( \
      const flume::SchemeRows&, const flume::Physics<2>&);                            \
  template std::unique_ptr<flume::Scheme<3>> flume::make_kernel_scheme<3, KERNEL<3>>( \
      const flume::SchemeRows&, const flume::Physics<3>&)
