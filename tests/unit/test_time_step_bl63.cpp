// BL (63)'s time step (time_step.hpp) by hand, and its path for one smoothing length (the
// largest |v|^2 and |a|^2 of a block, then one evaluation) against the per-particle minimum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <random>

#include "flume/integrators/time_step.hpp"
#include "flume/schemes/physics.hpp"

namespace flume {
namespace {

Physics<2> water(double mu) {
  Physics<2> phys;
  phys.eos.rho0 = 1000.0;
  phys.eos.gamma = 7.0;
  phys.eos.kappa = 1000.0 * 100.0 / 7.0;  // c0 = 10 m/s
  phys.mu = mu;
  return phys;
}

TEST(StepLimit, Bl63ByHandOnBothPaths) {
  const StepLimit<2> limit(water(0.0), 0.3);
  ParticleSet<2> ps;
  const double h = 0.01;
  ps.add_real(0, Vec<2>{{0.0, 0.0}}, Vec<2>{{3.0, 4.0}}, 0.1, 1000.0, h);
  ps.add_real(1, Vec<2>{{0.1, 0.0}}, Vec<2>{{0.0, 1.0}}, 0.1, 1000.0, h);
  ps.a[0] = Vec<2>{{0.0, 0.0}};
  ps.a[1] = Vec<2>{{0.0, 0.0}};
  // The acoustic limit of the faster particle, C h / (c0 + |v|) = 0.3 * 0.01 / 15.
  EXPECT_DOUBLE_EQ(limit.least(ps, 0, 2), 0.3 * 0.01 / 15.0);
  EXPECT_DOUBLE_EQ(limit.least(ps, 0, 2, h), 0.3 * 0.01 / 15.0);
  // The body-force limit 0.25 sqrt(h / |a|) of the particle with the larger |a| (5e4 m/s^2).
  ps.a[1] = Vec<2>{{3.0e4, 4.0e4}};
  ps.a[0] = Vec<2>{{1.0, 0.0}};
  EXPECT_DOUBLE_EQ(limit.least(ps, 0, 2), 0.25 * std::sqrt(0.01 / 5.0e4));
  EXPECT_DOUBLE_EQ(limit.least(ps, 0, 2, h), 0.25 * std::sqrt(0.01 / 5.0e4));
  // The explicit-diffusion limit 0.125 h^2 rho0 / mu with a large viscosity.
  const StepLimit<2> viscous(water(1000.0), 0.3);
  ps.a[1] = Vec<2>{{0.0, 0.0}};
  EXPECT_DOUBLE_EQ(viscous.least(ps, 0, 2, h), 0.125 * h * h * 1000.0 / 1000.0);
  // No particle: no limit.
  EXPECT_EQ(limit.least(ps, 1, 1, h), std::numeric_limits<double>::infinity());
}

// Each term of dt_a falls as |v_a| or |a_a| grows, so the minimum over a block is the terms at
// its largest |v|^2 and |a|^2, rounded the same way: the two paths agree to the bit (EXPECT_EQ,
// not a tolerance), over blocks of every size from 1 and starts that are not aligned.
TEST(StepLimit, OneSmoothingLengthGivesThePerParticleMinimumToTheBit) {
  const double h = 1.3e-3;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  // Each of the three terms sets the step somewhere: accelerations of 800 m/s^2 leave the
  // acoustic limit (about 2.7e-5 s) the least, 1e6 m/s^2 the body force (about 9e-6 s), and
  // mu = 50 Pa s the viscous one (4.2e-6 s).
  for (const double a_scale : {800.0, 1.0e6}) {
    ParticleSet<2> ps;
    for (std::size_t i = 0; i < 600; ++i) {
      ps.add_real(static_cast<long>(i), Vec<2>{{0.0, 0.0}}, Vec<2>{{u(rng), u(rng)}}, 0.1, 1000.0,
                  h);
      ps.a[i] = Vec<2>{{a_scale * unit(rng), a_scale * unit(rng)}};
    }
    for (const double mu : {0.0, 1e-3, 50.0}) {
      const StepLimit<2> limit(water(mu), 0.3);
      for (std::size_t b = 0; b < 600; b += 37)
        for (std::size_t e = b + 1; e <= 600; e += 53)
          EXPECT_EQ(limit.least(ps, b, e, h), limit.least(ps, b, e)) << b << " " << e;
    }
  }
}

}  // namespace
}  // namespace flume
