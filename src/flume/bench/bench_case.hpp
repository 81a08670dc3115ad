// The case `flume bench` measures: the bundled dam break (cases/dam_break.toml) scaled to a
// particle count, in the configuration of the speed issue (Wendland C2 kernel, artificial
// viscosity alpha = 0.02, inviscid, no snapshots), built through the same --set overrides a
// user would pass to `flume run`, so the benchmark runs exactly a case a user can run.
#pragma once

#include <string>
#include <vector>

#include "flume/case/case_spec.hpp"

namespace flume {

// DualSPHysics's kernel support in particle spacings (2h = 2.83 dx with Wendland C2).
inline constexpr double kBenchDefaultSupport = 2.83;

// The --set overrides of the bundled dam break for `particles` particles (the square water
// column of side `column` m becomes round(sqrt(particles))^2 particles) with kernel support
// `support` spacings. Spacing and h/dx are printed with 17 significant digits so that the case
// file a user writes from them is the same case.
std::vector<std::string> bench_overrides(const std::string& preset, double particles,
                                         double support, double column);

// The resolved case. Throws InputError (exit status 2) for an unknown preset, a particle count
// below 1 or a support that the case file rejects.
CaseSpec bench_case(const std::string& preset, double particles, double support);

// Measured steps when --steps is not given, chosen so that a run takes a few seconds on one
// core: 200 up to 3e4 particles, 50 up to 3e5, 10 above.
int bench_default_steps(double particles);

}  // namespace flume
