// Building a scheme for one kernel type: defined in schemes/instances/, one translation unit per
// kernel, so that the sweeps of the four kernels compile in parallel (each unit instantiates
// every scheme in 2D and 3D).
#pragma once

#include <memory>

#include "flume/schemes/registry.hpp"

namespace flume {

// The scheme for these rows with kernel K, or null when no scheme combines them.
template <int D, class K>
std::unique_ptr<Scheme<D>> make_kernel_scheme(const SchemeRows& rows, const Physics<D>& phys);

}  // namespace flume
