// Linear and angular momentum of the BL schemes with no external force and no walls (BL section
// 3, spec/methods.md "What flume's tests check"):
// - every preset keeps total linear momentum to round-off, with and without viscosity (an
//   antisymmetric pair force; for CSPH the identity sum_a V_a grad W~_a(x_b) = 0);
// - inviscid central forces (BL (7), BL (20) with mu = 0, BL 3.3.1) also keep the staggered
//   leap-frog angular momentum sum m x^{n+1} x v^{n+1/2} to round-off.
#include <gtest/gtest.h>

#include <random>

#include "flume/case/build_simulation.hpp"
#include "flume/schemes/registry.hpp"
#include "flume/sim/diagnostics.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

// A 12 x 12 block of water, away from the origin, with jittered positions and random velocities
// of about 1 m/s, in an open box large enough that nothing leaves it in the test's time.
Simulation<2> cloud(const std::string& preset, double mu, double alpha = 0.0) {
  const auto spec = test::spec_from(fmt::format(R"(
[case]
name = "cloud"
[particles]
spacing = 0.01
[scheme]
preset = "{}"
alpha = {}
beta = {}
[fluid]
viscosity = {}
gravity = [0.0, 0.0]
[eos]
sound_speed = 20.0
[domain]
min = [-1.0, -1.0]
max = [2.0, 2.0]
[boundaries]
x_min = "open"
x_max = "open"
y_min = "open"
y_max = "open"
[[fluid_blocks]]
min = [0.3, 0.5]
max = [0.42, 0.62]
hydrostatic = false
)",
                                                preset, alpha, 2 * alpha, mu));
  const auto phys = build_physics<2>(spec);
  auto ps = build_particles<2>(spec, phys);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    for (int k = 0; k < 2; ++k) {
      ps.x[i][k] += 0.2 * spec.spacing * u(rng);
      ps.v[i][k] = u(rng);
      ps.v_half[i][k] = ps.v[i][k];
    }
    ps.rho[i] *= 1.0 + 0.01 * u(rng);  // also a non-uniform pressure for the continuity scheme
  }
  const auto walls = test::open_box<2>(-1.0, 2.0);
  SimulationConfig<2> config;
  config.cfl = 0.3;
  return Simulation<2>(ps, walls,
                       make_scheme<2>(SchemeRows{spec.density, spec.force, spec.correction},
                                      *kernel_from_name(spec.kernel), phys),
                       phys, config);
}

struct Totals {
  Vec<2> momentum;
  double angular = 0.0;
  double sum_mv = 0.0;   // sum m |v|: the scale of the momentum round-off
  double sum_mxv = 0.0;  // sum m |x| |v|: the scale of the angular momentum round-off
};

Totals totals(const ParticleSet<2>& ps) {
  Totals t;
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    t.momentum += ps.v_half[i] * ps.m[i];
    t.angular += ps.m[i] * cross_z(ps.x[i], ps.v_half[i]);
    t.sum_mv += ps.m[i] * norm(ps.v_half[i]);
    t.sum_mxv += ps.m[i] * norm(ps.x[i]) * norm(ps.v_half[i]);
  }
  return t;
}

class LinearMomentum : public ::testing::TestWithParam<std::string> {};
class CentralForces : public ::testing::TestWithParam<std::string> {};

TEST_P(LinearMomentum, KeptToRoundOffWithViscosity) {
  // Physical viscosity BL (24) and artificial viscosity W (3.18) (alpha = 0.1, beta = 0.2) on.
  auto sim = cloud(GetParam(), 0.5, 0.1);
  const Totals before = totals(sim.particles());
  for (int s = 0; s < 100; ++s)
    sim.step(1.0);
  const Totals after = totals(sim.particles());
  // The pair forces cancel exactly in exact arithmetic; each step adds O(1e-16) relative
  // round-off per particle sum, so 100 steps stay far below 1e-12 of sum m |v| (cases.md BL-1).
  for (int k = 0; k < 2; ++k)
    EXPECT_LT(std::abs(after.momentum[k] - before.momentum[k]), 1e-12 * before.sum_mv)
        << GetParam() << " axis " << k;
  // Not vacuous: the particles did interact (the kinetic state changed).
  EXPECT_GT(std::abs(after.sum_mv - before.sum_mv), 1e-6 * before.sum_mv);
}

TEST_P(CentralForces, KeepAngularMomentumWhenInviscid) {
  auto sim = cloud(GetParam(), 0.0);
  const Totals before = totals(sim.particles());
  for (int s = 0; s < 100; ++s)
    sim.step(1.0);
  const Totals after = totals(sim.particles());
  // Central pair forces and the staggered leap-frog measure (BL 3.3.1, leapfrog.hpp): exact up
  // to round-off; 1e-9 of sum m |x| |v| is the tolerance of cases.md BL-1.
  EXPECT_LT(std::abs(after.angular - before.angular), 1e-9 * before.sum_mxv) << GetParam();
}

// CSPH's pair force is not central: its angular momentum rests on BL (41) instead (test_csph.cpp).
INSTANTIATE_TEST_SUITE_P(Presets, LinearMomentum,
                         ::testing::Values("standard", "continuity", "inconsistent", "csph"));
INSTANTIATE_TEST_SUITE_P(Presets, CentralForces,
                         ::testing::Values("standard", "continuity", "inconsistent"));

// Standard SPH with viscosity does not keep angular momentum (BL 3.3.1: the viscous pair force is
// not central): a check that the angular test above can fail.
TEST(MomentumConservation, ViscousStandardSphLosesAngularMomentum) {
  auto sim = cloud("standard", 0.5);
  const Totals before = totals(sim.particles());
  for (int s = 0; s < 100; ++s)
    sim.step(1.0);
  const Totals after = totals(sim.particles());
  EXPECT_GT(std::abs(after.angular - before.angular), 1e-6 * before.sum_mxv);
}

}  // namespace
}  // namespace flume

namespace flume {
namespace {

// The 3D instantiation runs the same code: a 6 x 6 x 6 block with random velocities, viscous,
// no gravity, no walls, keeps its linear momentum to round-off for every preset.
class LinearMomentum3D : public ::testing::TestWithParam<std::string> {};

TEST_P(LinearMomentum3D, KeptToRoundOff) {
  const auto spec = test::spec_from(fmt::format(R"(
[case]
name = "cloud3d"
dimension = 3
[particles]
spacing = 0.01
[scheme]
preset = "{}"
[fluid]
viscosity = 0.5
gravity = [0.0, 0.0, 0.0]
[eos]
sound_speed = 20.0
[domain]
min = [-1.0, -1.0, -1.0]
max = [2.0, 2.0, 2.0]
[[fluid_blocks]]
min = [0.3, 0.5, 0.2]
max = [0.36, 0.56, 0.26]
hydrostatic = false
)",
                                                GetParam()));
  const auto phys = build_physics<3>(spec);
  auto ps = build_particles<3>(spec, phys);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    for (int k = 0; k < 3; ++k)
      ps.v[i][k] = u(rng);
    ps.v_half[i] = ps.v[i];
  }
  Simulation<3> sim(ps, test::open_box<3>(-1.0, 2.0),
                    make_scheme<3>(SchemeRows{spec.density, spec.force, spec.correction},
                                   *kernel_from_name(spec.kernel), phys),
                    phys, SimulationConfig<3>{});
  Vec<3> before, after;
  double scale = 0.0;
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    before += ps.v_half[i] * ps.m[i];
    scale += ps.m[i] * norm(ps.v_half[i]);
  }
  for (int s = 0; s < 40; ++s)
    sim.step(1.0);
  for (std::size_t i = 0; i < sim.particles().n_real; ++i)
    after += sim.particles().v_half[i] * sim.particles().m[i];
  // Same round-off argument and bound as in 2D (cases.md BL-1).
  for (int k = 0; k < 3; ++k)
    EXPECT_LT(std::abs(after[k] - before[k]), 1e-12 * scale) << k;
}

INSTANTIATE_TEST_SUITE_P(Presets, LinearMomentum3D,
                         ::testing::Values("standard", "continuity", "inconsistent", "csph"));

}  // namespace
}  // namespace flume
