// Moving walls (boundaries/wall_motion.hpp, box_walls.hpp) in whole simulations. Galilean
// invariance: a tank whose two side walls move at U, holding water that moves at U, is the
// still-water tank seen from a moving frame. Step for step, every particle must be where the
// static tank's is, shifted by U t, with its velocity plus U. This sees every part of the moving
// wall at once: where the ghosts stand (the wall's place at t^n), the velocity they carry
// (v' = P v + (I - P) u_w: a wrong factor or sign gives errors of order U = 0.5 m/s within a
// step), corners with the static floor, and the put-back and escape checks against the moving
// walls. The frames differ only by round-off in x + U t (1e-16 of the positions), which the
// acoustic dynamics of 200 steps amplify to about 1e-13: the bound 1e-9 is far above that and far
// below any error of the mechanism.
#include <gtest/gtest.h>

#include <map>

#include "flume/case/build_simulation.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

constexpr double kU = -0.5;  // m/s

std::string tank_toml(const std::string& preset, double u, bool moving) {
  std::string toml = fmt::format(R"(
[case]
name = "moving_tank"
end_time = 0.04
dt = 2e-4
[particles]
spacing = 0.005
[scheme]
preset = "{}"
alpha = 0.1
[fluid]
viscosity = 0.1
[eos]
sound_speed = 15.0
[domain]
min = [0.0, 0.0]
max = [0.1, 0.1]
[boundaries]
x_min = "free_slip"
x_max = "no_slip"
[[fluid_blocks]]
min = [0.0, 0.0]
max = [0.1, 0.05]
velocity = [{}, 0.0]
)",
                                 preset, u);
  if (moving)
    toml += fmt::format(
        "[[moving_walls]]\nside = \"x_min\"\nvelocity = {0}\n[[moving_walls]]\nside = "
        "\"x_max\"\nvelocity = {0}\n",
        u);
  return toml;
}

class MovingTank : public ::testing::TestWithParam<std::string> {};

TEST_P(MovingTank, IsTheStillTankInAMovingFrame) {
  const std::string preset = GetParam();
  auto still = build_simulation<2>(test::spec_from(tank_toml(preset, 0.0, false)));
  auto moving = build_simulation<2>(test::spec_from(tank_toml(preset, kU, true)));
  for (int n = 0; n < 200; ++n) {
    still.step(1.0);
    moving.step(1.0);
  }
  ASSERT_EQ(still.time(), moving.time());
  const double t = moving.time();
  std::map<std::int64_t, std::size_t> at;
  const auto& ps = still.particles();
  const auto& pm = moving.particles();
  for (std::size_t i = 0; i < ps.n_real; ++i)
    at[ps.id[i]] = i;
  ASSERT_EQ(ps.n_real, pm.n_real);
  double dx_max = 0.0, dv_max = 0.0, v_still = 0.0;
  for (std::size_t i = 0; i < pm.n_real; ++i) {
    const std::size_t s = at.at(pm.id[i]);
    Vec<2> shifted = ps.x[s], boosted = ps.v[s];
    shifted[0] += kU * t;
    boosted[0] += kU;
    dx_max = std::max(dx_max, norm(pm.x[i] - shifted));
    dv_max = std::max(dv_max, norm(pm.v[i] - boosted));
    v_still = std::max(v_still, norm(ps.v[s]));
  }
  EXPECT_LT(dx_max, 1e-9) << preset;
  EXPECT_LT(dv_max, 1e-9) << preset;
  // The still tank is not trivially still: its start-up acoustic motion is what is compared.
  EXPECT_GT(v_still, 1e-4) << preset;
}

INSTANTIATE_TEST_SUITE_P(Presets, MovingTank, ::testing::Values("continuity", "csph", "standard"));

}  // namespace
}  // namespace flume
