#include "flume/schemes/registry.hpp"

#include <fmt/format.h>

#include "flume/core/error.hpp"
#include "flume/schemes/kernel_schemes.hpp"

namespace flume {

template <int D>
std::unique_ptr<Scheme<D>> make_scheme(const SchemeRows& rows, KernelKind kernel,
                                       const Physics<D>& phys) {
  auto scheme = with_kernel<D>(
      kernel, [&](auto k) { return make_kernel_scheme<D, decltype(k)>(rows, phys); });
  if (!scheme)
    throw InputError(fmt::format(
        "no scheme combines density '{}', force '{}' and correction '{}'; available: {}",
        rows.density, rows.force, rows.correction, fmt::join(scheme_combinations(), ", ")));
  return scheme;
}

template std::unique_ptr<Scheme<2>> make_scheme<2>(const SchemeRows&, KernelKind,
                                                   const Physics<2>&);
template std::unique_ptr<Scheme<3>> make_scheme<3>(const SchemeRows&, KernelKind,
                                                   const Physics<3>&);

}  // namespace flume
