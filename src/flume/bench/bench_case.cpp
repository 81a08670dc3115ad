#include "flume/bench/bench_case.hpp"

#include <fmt/format.h>

#include <cmath>

#include "flume/case/case_reader.hpp"
#include "flume/core/error.hpp"
#include "flume/validation/bundled_cases.hpp"

namespace flume {

std::vector<std::string> bench_overrides(const std::string& preset, double particles,
                                         double support, double column) {
  const double side = std::round(std::sqrt(particles));
  return {
      fmt::format("scheme.preset=\"{}\"", preset),
      fmt::format("particles.spacing={:.17g}", column / side),
      "scheme.kernel=\"wendland_c2\"",
      // Wendland C2 reaches 2h: support / 2 spacings per h.
      fmt::format("scheme.h_over_dx={:.17g}", support / 2.0),
      "scheme.alpha=0.02",
      "fluid.viscosity=0.0",
      "output.snapshot_interval=0.0",
  };
}

CaseSpec bench_case(const std::string& preset, double particles, double support) {
  if (!(particles >= 1.0))
    throw InputError(fmt::format("bench: --particles {}: must be at least 1", particles));
  if (!(support > 0.0))
    throw InputError(fmt::format("bench: --support {}: must be positive", support));
  const auto file = bundled_case("dam_break");
  // The column's side from the case itself (0.05715 m in the bundled file), so the scaling
  // follows the case if it ever changes.
  const CaseSpec base = read_case(file, {});
  const auto& block = base.blocks.at(0);
  const double column = block.max.at(0) - block.min.at(0);
  try {
    return read_case(file, bench_overrides(preset, particles, support, column));
  } catch (const InputError& e) {
    throw InputError(fmt::format("bench: preset {}, {} particles, support {}: {}", preset,
                                 particles, support, e.what()));
  }
}

int bench_default_steps(double particles) {
  if (particles <= 3e4) return 200;
  if (particles <= 3e5) return 50;
  return 10;
}

}  // namespace flume
