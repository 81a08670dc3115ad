// The kernel registry: the one place where the kernel chosen at run time (by name, from the
// case file) becomes a compile-time type. Everything inside the particle loops is templated on
// the kernel type, so W and dW/dr inline; with_kernel is the single dispatch point.
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "flume/kernels/cubic_spline.hpp"
#include "flume/kernels/gaussian.hpp"
#include "flume/kernels/quintic_spline.hpp"
#include "flume/kernels/wendland_c2.hpp"

namespace flume {

enum class KernelKind { cubic_spline, quintic_spline, gaussian, wendland_c2 };

inline constexpr std::array<KernelKind, 4> kernel_kinds{
    KernelKind::cubic_spline, KernelKind::quintic_spline, KernelKind::gaussian,
    KernelKind::wendland_c2};

// Calls f(K<D>{}) for the kernel type K matching k and returns what f returns (f must return
// the same type for every kernel, as with std::visit).
template <int D, class F>
constexpr decltype(auto) with_kernel(KernelKind k, F&& f) {
  switch (k) {  // no default: -Wswitch then flags a kernel added to the enum but not here
    case KernelKind::cubic_spline:
      return std::forward<F>(f)(CubicSpline<D>{});
    case KernelKind::quintic_spline:
      return std::forward<F>(f)(QuinticSpline<D>{});
    case KernelKind::gaussian:
      return std::forward<F>(f)(Gaussian<D>{});
    case KernelKind::wendland_c2:
      return std::forward<F>(f)(WendlandC2<D>{});
  }
  throw std::invalid_argument("with_kernel: invalid KernelKind");
}

// Name and support do not depend on the dimension, so any D will do.
constexpr std::string_view kernel_name(KernelKind k) {
  return with_kernel<1>(k, [](auto kernel) { return decltype(kernel)::name; });
}

// Support radius in units of h.
constexpr double kernel_support(KernelKind k) {
  return with_kernel<1>(k, [](auto kernel) { return decltype(kernel)::support; });
}

constexpr std::optional<KernelKind> kernel_from_name(std::string_view name) {
  for (KernelKind k : kernel_kinds)
    if (kernel_name(k) == name) return k;
  return std::nullopt;
}

// The valid names, in enum order (for error messages and --help).
inline const std::vector<std::string>& kernel_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (KernelKind k : kernel_kinds)
      v.emplace_back(kernel_name(k));
    return v;
  }();
  return names;
}

}  // namespace flume
