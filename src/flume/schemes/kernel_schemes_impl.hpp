// The body of make_kernel_scheme, included by the one translation unit of each kernel.
#pragma once

#include "flume/equations/force_bonet_lok_20.hpp"
#include "flume/equations/force_bonet_lok_7.hpp"
#include "flume/schemes/continuity_scheme.hpp"
#include "flume/schemes/csph_scheme.hpp"
#include "flume/schemes/kernel_schemes.hpp"
#include "flume/schemes/summation_scheme.hpp"

namespace flume {

template <int D, class K>
std::unique_ptr<Scheme<D>> make_kernel_scheme(const SchemeRows& rows, const Physics<D>& phys) {
  if (rows.density == "summation" && rows.force == "bl7")
    return std::make_unique<SummationScheme<D, K, ForceBonetLok7>>(phys);
  if (rows.density == "summation" && rows.force == "bl20")
    return std::make_unique<SummationScheme<D, K, ForceBonetLok20>>(phys);
  if (rows.density == "continuity" && rows.force == "bl20")
    return std::make_unique<ContinuityScheme<D, K>>(phys);
  if (rows.density == "continuity" && rows.force == "bl59")
    return std::make_unique<CsphScheme<D, K>>(phys);
  return nullptr;
}

}  // namespace flume

// Instantiates make_kernel_scheme for kernel template KERNEL in 2D and 3D.
#define FLUME_KERNEL_SCHEMES(KERNEL)                                                  \
  template std::unique_ptr<flume::Scheme<2>> flume::make_kernel_scheme<2, KERNEL<2>>( \
      const flume::SchemeRows&, const flume::Physics<2>&);                            \
  template std::unique_ptr<flume::Scheme<3>> flume::make_kernel_scheme<3, KERNEL<3>>( \
      const flume::SchemeRows&, const flume::Physics<3>&)
