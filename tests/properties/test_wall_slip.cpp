// Mirror walls, W 6.1: a layer of fluid sliding uniformly along the floor feels no force from a
// free-slip floor (the ghosts move with it, so the velocity field stays uniform) and is braked by
// a no-slip floor (the ghosts move the other way: wall shear).
#include <gtest/gtest.h>

#include "flume/case/build_simulation.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

// x-momentum of a 0.1 m x 0.05 m layer (dx = 5 mm) sliding at 1 m/s on the floor, mu = 0.5 Pa s,
// no gravity, open everywhere but the floor, after 50 steps; returns (before, after).
std::pair<double, double> sliding_layer(const std::string& floor, const std::string& preset) {
  const auto spec = test::spec_from(fmt::format(R"(
[case]
name = "sliding_layer"
[particles]
spacing = 0.005
[scheme]
preset = "{}"
[fluid]
viscosity = 0.5
gravity = [0.0, 0.0]
[eos]
sound_speed = 20.0
[domain]
min = [-1.0, 0.0]
max = [2.0, 1.0]
[boundaries]
x_min = "open"
x_max = "open"
y_min = "{}"
y_max = "open"
[[fluid_blocks]]
min = [0.0, 0.0]
max = [0.1, 0.05]
velocity = [1.0, 0.0]
hydrostatic = false
)",
                                                preset, floor));
  auto sim = build_simulation<2>(spec);
  auto px = [](const ParticleSet<2>& ps) {
    double p = 0.0;
    for (std::size_t i = 0; i < ps.n_real; ++i)
      p += ps.m[i] * ps.v_half[i][0];
    return p;
  };
  const double before = px(sim.particles());
  for (int s = 0; s < 50; ++s)
    sim.step(1.0);
  return {before, px(sim.particles())};
}

class WallSlip : public ::testing::TestWithParam<std::string> {};

TEST_P(WallSlip, FreeSlipFloorExertsNoTangentialForce) {
  const auto [before, after] = sliding_layer("free_slip", GetParam());
  // Only round-off: the uniform field has an exactly zero velocity gradient with its mirror
  // ghosts; edge effects of the open sides act along x symmetrically and cancel to round-off.
  EXPECT_NEAR(after, before, 1e-12 * before) << GetParam();
}

TEST_P(WallSlip, NoSlipFloorBrakesTheLayer) {
  const auto [before, after] = sliding_layer("no_slip", GetParam());
  // Wall shear ~ mu 2U/dx = 200 Pa on 0.1 m for ~5 ms is ~2 % of the layer's momentum (5 kg m/s
  // per metre); the bounds only check that the brake is there and is not wildly off.
  EXPECT_LT(after, 0.995 * before) << GetParam();
  EXPECT_GT(after, 0.8 * before) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Presets, WallSlip, ::testing::Values("continuity", "standard", "csph"));

}  // namespace
}  // namespace flume
