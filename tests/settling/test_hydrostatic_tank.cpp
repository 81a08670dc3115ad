// Still water in a tank (W-3 of spec/cases.md, the issue's acceptance test): started from the
// hydrostatic density of the Tait EOS (the column integrated), the water must stay at rest with
// a bottom pressure within 1 % of rho0 g H (the integrated column's own bed pressure is 0.25 %
// above rho0 g H: its compression weighs). Checked for the continuity preset: with the summation
// density BL (1) the particles at a free surface miss half their kernel support, their density
// falls well below rho0 and the Tait EOS puts them in strong tension, so still water is not an
// equilibrium of the standard preset (the surface layer collapses); that is a property of BL (1),
// not a bug. Also checked with the Shepard density filter W (6.3) every 40 steps, as W runs it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <tuple>
#include <vector>

#include "flume/case/build_simulation.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

// A tank 0.2 m wide with water H = 0.1 m deep, dx = 5 mm (40 x 20 particles), free-slip walls,
// mu = 0.5 Pa s to damp the start-up acoustic waves, 0.5 s of simulated time (about 35 acoustic
// crossings of the depth at c0 = 14 m/s).
constexpr double kH = 0.1;
constexpr double kDx = 0.005;

std::string tank_toml(const std::string& preset, int shepard_every, const std::string& filter,
                      const std::string& ghost_pressure = "mirrored") {
  return fmt::format(R"(
[case]
name = "still_water"
end_time = 0.5
[particles]
spacing = {}
[scheme]
preset = "{}"
shepard_every = {}
density_filter = "{}"
[fluid]
viscosity = 0.5
[domain]
min = [0.0, 0.0]
max = [0.2, 0.2]
[boundaries]
ghost_pressure = "{}"
[[fluid_blocks]]
min = [0.0, 0.0]
max = [0.2, {}]
)",
                     kDx, preset, shepard_every, filter, ghost_pressure, kH);
}

// (preset, steps between density filters W (6.3), 0 = none, the filter's average, the mirror
// ghosts' pressure)
using TankParam = std::tuple<std::string, int, std::string, std::string>;
class HydrostaticTank : public ::testing::TestWithParam<TankParam> {};

TEST_P(HydrostaticTank, BottomPressureMatchesRhoGH) {
  const auto& [preset, shepard_every, filter, ghosts] = GetParam();
  const auto spec = test::spec_from(tank_toml(preset, shepard_every, filter, ghosts));
  auto sim = build_simulation<2>(spec);
  const double g = 9.81, rho0 = spec.rho0;
  // Bottom pressure as a gauge reads it: each particle's pressure in the four bottom rows
  // extrapolated to the floor with the hydrostatic gradient, averaged over the rows and over the
  // last 0.1 s (sampled every step: the start-up acoustic oscillation, period 4H/c0 = 0.03 s,
  // averages out). Four rows, an even number: the pressure carries a few-percent odd-even
  // row-to-row mode, which a gradient exact for linear fields (CSPH) cannot see (the rows above
  // and below a particle cancel), so it persists; three rows (two of one sign) read it as +1.3 %.
  double sum = 0.0, vmax = 0.0;
  long count = 0;
  while (sim.time() < spec.end_time) {
    sim.step(spec.end_time - sim.time());
    if (sim.time() < spec.end_time - 0.1) continue;
    const auto& ps = sim.particles();
    for (std::size_t i = 0; i < ps.n_real; ++i) {
      vmax = std::max(vmax, norm(ps.v[i]));
      if (ps.x[i][1] < 4 * kDx && ps.x[i][0] > 0.02 && ps.x[i][0] < 0.18) {
        sum += ps.p[i] + rho0 * g * ps.x[i][1];
        ++count;
      }
    }
  }
  ASSERT_GT(count, 1000);
  const double p_bottom = sum / static_cast<double>(count);
  // The issue's tolerance: 1 % of rho0 g H (measured: continuity -0.65 %, csph +0.33 %, continuity
  // with the filter -0.65 %).
  EXPECT_NEAR(p_bottom, rho0 * g * kH, 0.01 * rho0 * g * kH)
      << preset << " " << shepard_every << " " << filter;
  // At rest: spurious velocities far below the free-fall speed sqrt(2 g H) = 1.4 m/s.
  EXPECT_LT(vmax, 0.05 * std::sqrt(2 * g * kH)) << preset << " " << shepard_every << " " << filter;
}

// With W's filter interval of 40 steps too: the filter averages over a one-sided kernel at the
// free surface, and still water must remain still water; so must it under the first-order filter.
INSTANTIATE_TEST_SUITE_P(Presets, HydrostaticTank,
                         ::testing::Values(TankParam{"continuity", 0, "shepard", "mirrored"},
                                           TankParam{"csph", 0, "shepard", "mirrored"},
                                           TankParam{"continuity", 40, "shepard", "mirrored"},
                                           TankParam{"continuity", 40, "first_order", "mirrored"},
                                           TankParam{"continuity", 0, "shepard", "hydrostatic"},
                                           TankParam{"csph", 40, "shepard", "hydrostatic"}));

// The bottom row's mean height after 0.5 s of still water under W (6.3)'s filter every 10 steps
// (continuity preset; the tank above), minus its starting height dx / 2.
double bottom_row_sinking(const std::string& ghost_pressure) {
  const auto spec = test::spec_from(tank_toml("continuity", 10, "shepard", ghost_pressure));
  auto sim = build_simulation<2>(spec);
  std::vector<std::uint64_t> bottom;
  for (std::size_t i = 0; i < sim.particles().n_real; ++i)
    if (sim.particles().x[i][1] < kDx) bottom.push_back(sim.particles().id[i]);
  while (sim.time() < spec.end_time)
    sim.step(spec.end_time - sim.time());
  const auto& ps = sim.particles();
  double sum = 0.0;
  long count = 0;
  for (std::size_t i = 0; i < ps.n_real; ++i)
    if (std::find(bottom.begin(), bottom.end(), ps.id[i]) != bottom.end()) {
      sum += ps.x[i][1];
      ++count;
    }
  EXPECT_EQ(count, static_cast<long>(bottom.size()));
  return sum / static_cast<double>(count) - 0.5 * kDx;
}

// boundaries.ghost_pressure: with W 6.1's mirror ghosts (p and rho copied) the pressure folds into
// a V at the floor and the filter, averaging across it, lowers the bottom row's density at every
// filtering, so the row sinks toward its own ghosts (issue 10: the periodic tank's floor
// collapses after 2.5 s); with the hydrostatic step in the ghosts' pressure the profile runs on
// through the floor and the row stays.
TEST(HydrostaticGhosts, HoldTheBottomRowUnderTheFilter) {
  const double mirrored = bottom_row_sinking("mirrored");
  const double hydrostatic = bottom_row_sinking("hydrostatic");
  // Measured: mirrored -1.18e-4 m (0.024 dx), hydrostatic 5e-7 m. The bounds tell the two
  // apart: the mirrored row sinks by more than 0.01 dx, the hydrostatic one moves by less than a
  // tenth of that.
  std::printf("bottom row moved: mirrored %.3e m, hydrostatic %.3e m\n", mirrored, hydrostatic);
  EXPECT_LT(mirrored, -0.01 * kDx);
  EXPECT_LT(std::abs(hydrostatic), 0.001 * kDx);
}

}  // namespace
}  // namespace flume
