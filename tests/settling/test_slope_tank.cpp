// Still water against a plane beach of repulsive boundary particles (boundaries/
// repulsive_walls.hpp; the issue's "test a still tank on a slope"), in whole simulations: a
// 1 m tank 0.15 m deep whose right end is a 1:2 beach, W's wave-tank numerics (weak SPH, RK2),
// at 0.01875 m spacing (8 rows) for 1 s. The water settles against the beach, a little lower than
// it started (it fills part of the wall's reach, where no particle was placed), and then must be
// at rest, in hydrostatic balance with the level it settled at, with no particle behind the beach.
#include <gtest/gtest.h>

#include <cmath>

#include "flume/case/build_simulation.hpp"
#include "flume/probes/wave_probes.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

std::string slope_tank_toml(const std::string& force) {
  return fmt::format(R"(
[case]
name = "slope_tank"
end_time = 1.0
dt = 9.375e-5
[particles]
spacing = 0.01875
[scheme]
preset = "wsph"
kernel = "cubic_spline"
h_over_dx = 1.3
integrator = "runge_kutta"
alpha = 0.5
beta = 1.0
shepard_every = 40
[fluid]
gravity = [0.0, -9.81]
[eos]
sound_speed = 83.0
[domain]
min = [0.0, 0.0]
max = [1.0, 0.3]
[[fluid_blocks]]
min = [0.0, 0.0]
max = [1.0, 0.15]
[[repulsive_walls]]
from = [0.5, 0.0]
to = [1.0, 0.25]
force = "{}"
)",
                     force);
}

class SlopeTank : public ::testing::TestWithParam<std::string> {};

TEST_P(SlopeTank, SettlesAtRestInHydrostaticBalanceInFrontOfTheBeach) {
  const auto spec = test::spec_from(slope_tank_toml(GetParam()));
  auto sim = build_simulation<2>(spec);
  const std::size_t n = sim.particles().n_real;
  double mass = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    mass += sim.particles().m[i];
  while (sim.time() < spec.end_time)
    sim.step(spec.end_time - sim.time());
  const auto& ps = sim.particles();
  ASSERT_EQ(ps.n_real, n);
  // In front of the beach: (x - toe) . n >= 0 with n = (-1, 2) / sqrt(5), over its length.
  double speed = 0.0, m_end = 0.0, kinetic = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = (-(ps.x[i][0] - 0.5) + 2.0 * ps.x[i][1]) / std::sqrt(5.0);
    if (ps.x[i][0] > 0.5) {
      EXPECT_GE(y, 0.0) << "particle " << ps.id[i] << " behind the beach";
    }
    speed = std::max(speed, norm(ps.v[i]));
    kinetic += ps.m[i] * norm2(ps.v[i]);
    m_end += ps.m[i];
  }
  EXPECT_NEAR(m_end, mass, 1e-12 * mass);
  // At rest: the residual motion after 1 s (the start's seiche, damped by alpha = 0.5) has an
  // rms speed of a few mm/s, a few thousandths of sqrt(g H) = 1.2 m/s; the start's push from a
  // wall placed inside its reach throws water off at metres per second (repulsive_walls.hpp).
  const double rms = std::sqrt(kinetic / m_end);
  EXPECT_LT(rms, 0.02) << GetParam() << " (fastest particle " << speed << " m/s)";
  // Hydrostatic balance with the level the water settled at: the bed pressure over the flat
  // bed (0.1 < x < 0.4 m) against rho0 g (H + the level at x = 0.25 m). 1 %: the still tank
  // reads within 0.2 % of rho0 g H at h = 1.3 dx (still_tank.toml), and the level from the
  // masses carries the B-spline's smoothing and the particles' noise, a few tenths of a per cent
  // of H at 8 rows.
  const double g = 9.81, rho0 = 1000.0, H = 0.15, dx = 0.01875;
  const auto still = read_still_water(ps, 0.1, 0.4, 0.0, rho0, g, dx);
  const auto depth = depth_profile(ps, nullptr, 0.0, 1.0, rho0, dx, false);
  const double level = depth.at(0.25);
  EXPECT_LT(std::abs(level - H), 0.5 * dx) << "the water moved by half a spacing or more";
  EXPECT_NEAR(still.bed_pressure, rho0 * g * level, 0.01 * rho0 * g * level) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Forces, SlopeTank, ::testing::Values("monaghan_kos", "lennard_jones"));

}  // namespace
}  // namespace flume
