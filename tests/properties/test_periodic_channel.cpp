// A periodic channel in whole simulations (W 6.1): a channel full of water moving uniformly
// along a periodic x must stay uniform. With the summation density BL (1) this sees the
// periodic ghosts: without them the particles at the ends would miss part of their kernel
// support, read a lower density and be pushed along x (accelerations of order c0^2 / h, a
// hundred m/s^2 here). It also sees the re-injection: over the run every particle crosses the
// end about once and the channel keeps its particles, its mass and its momentum. The uniform
// state is an equilibrium to round-off (every particle has the same neighbourhood), so the
// velocities stay (U, 0) to 1e-9 m/s, far above round-off (1e-13) and far below any error of
// the mechanism.
#include <gtest/gtest.h>

#include "flume/case/build_simulation.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

constexpr double kU = 0.5;  // m/s

std::string channel_toml(const std::string& preset, const std::string& x_sides) {
  return fmt::format(R"(
[case]
name = "periodic_channel"
end_time = 0.8
[particles]
spacing = 0.02
[scheme]
preset = "{}"
[fluid]
gravity = [0.0, 0.0]
[eos]
sound_speed = 5.0
[domain]
min = [0.0, 0.0]
max = [0.4, 0.2]
[boundaries]
x_min = "{}"
x_max = "{}"
[[fluid_blocks]]
min = [0.0, 0.0]
max = [0.4, 0.2]
velocity = [{}, 0.0]
hydrostatic = false
)",
                     preset, x_sides, x_sides, kU);
}

class PeriodicChannel : public ::testing::TestWithParam<std::string> {};

TEST_P(PeriodicChannel, UniformFlowStaysUniformAndEveryParticleComesBack) {
  const auto spec = test::spec_from(channel_toml(GetParam(), "periodic"));
  auto sim = build_simulation<2>(spec);
  const std::size_t n = sim.particles().n_real;
  ASSERT_EQ(n, 200u);
  while (sim.time() < spec.end_time)
    sim.step(spec.end_time - sim.time());
  const auto& ps = sim.particles();
  ASSERT_EQ(ps.n_real, n);
  double px = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(ps.v[i][0], kU, 1e-9) << GetParam() << " particle " << ps.id[i];
    EXPECT_NEAR(ps.v[i][1], 0.0, 1e-9) << GetParam() << " particle " << ps.id[i];
    EXPECT_NEAR(ps.rho[i], ps.rho[0], 1e-9 * ps.rho[0]);
    px += ps.m[i] * ps.v[i][0];
  }
  double mass = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    mass += ps.m[i];
  EXPECT_NEAR(px, mass * kU, 1e-12 * mass * kU);
  // 0.8 s at 0.5 m/s: every particle has gone once round the 0.4 m channel.
  EXPECT_NEAR(sim.time() * kU, 0.4, 1e-9);
}

TEST(PeriodicChannel, WithoutThePeriodicGhostsTheEndsArePushed) {
  // The same channel with open ends (no ghosts at x): the summation density of the end columns
  // is lower and the flow is no longer uniform within a few steps: what the test above would
  // see if the periodic ghosts were missing.
  auto spec = test::spec_from(channel_toml("standard", "open"));
  spec.end_time = 0.01;
  auto sim = build_simulation<2>(spec);
  while (sim.time() < spec.end_time)
    sim.step(spec.end_time - sim.time());
  double worst = 0.0;
  for (std::size_t i = 0; i < sim.particles().n_real; ++i)
    worst = std::max(worst, std::abs(sim.particles().v[i][0] - kU));
  EXPECT_GT(worst, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Presets, PeriodicChannel,
                         ::testing::Values("standard", "continuity", "csph", "rsph"));

}  // namespace
}  // namespace flume
