// Unit tests of the leap-frog integrator (src/flume/integrators/leapfrog.hpp) and of the time-step
// selection (src/flume/integrators/time_step.hpp).
//
// Leap-frog with the half-step start v^{1/2} = v^0 + (dt^1 / 2) a^0 and the variable-step kick
// v^{n+1/2} = v^{n-1/2} + (dt^n + dt^{n+1}) / 2 a^n is exact for a constant acceleration: the kicks
// telescope to v^{n+1/2} = v0 + a (t_n + dt^{n+1} / 2), so each drift adds
// dt^{n+1} (v0 + a (t_n + dt^{n+1} / 2)) = v0 dt + a (t_{n+1}^2 - t_n^2) / 2. There is no
// truncation error at all, only round-off. Two kinds of check follow from that:
//  * with dyadic data (steps, velocities, accelerations that are small multiples of powers of
//    two) every intermediate value is exactly representable, so the result must be bit-exact;
//  * with arbitrary data the error must stay at the round-off level of a sum of N terms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/core/vec.hpp"
#include "flume/integrators/leapfrog.hpp"
#include "flume/integrators/time_step.hpp"
#include "flume/schemes/physics.hpp"
#include "flume/schemes/registry.hpp"
#include "support/rates.hpp"

namespace flume {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Start {
  Vec<2> x, v, a;
};

ParticleSet<2> make_set(const std::vector<Start>& s) {
  ParticleSet<2> ps;
  for (std::size_t i = 0; i < s.size(); ++i) {
    ps.add_real(static_cast<std::int64_t>(i), s[i].x, s[i].v, 0.01, 1000.0, 0.02);
    ps.a[i] = s[i].a;
  }
  return ps;
}

// Dyadic starting states: every product and sum below fits in a double exactly.
const std::vector<Start> kDyadic{
    {{{0.5, 0.25}}, {{1.0, -0.5}}, {{0.0, -10.0}}},
    {{{-1.0, 2.0}}, {{0.0, 0.0}}, {{3.0, 0.5}}},
    {{{0.125, 0.0}}, {{-2.0, 4.0}}, {{-0.25, -8.0}}},
};

TEST(LeapFrog, ConstantAccelerationIsExactWithFixedStep) {
  auto ps = make_set(kDyadic);
  LeapFrog<2> lf;
  const double dt = 1.0 / 64.0;
  const int steps = 50;
  for (int n = 1; n <= steps; ++n) {
    lf.advance(ps, dt, false);
    const double t = n * dt;
    for (std::size_t i = 0; i < kDyadic.size(); ++i) {
      const auto& s = kDyadic[i];
      const Vec<2> x = s.x + s.v * t + s.a * (0.5 * t * t);
      const Vec<2> v = s.v + s.a * t;
      // Dyadic data: exact, no tolerance.
      ASSERT_EQ(ps.x[i], x) << "particle " << i << " step " << n;
      ASSERT_EQ(ps.v[i], v) << "particle " << i << " step " << n;
      // The staggered velocity is v at the mid-step, t - dt / 2.
      ASSERT_EQ(ps.v_half[i], s.v + s.a * (t - 0.5 * dt)) << "particle " << i << " step " << n;
    }
  }
}

TEST(LeapFrog, ConstantAccelerationIsExactWithVariableStep) {
  auto ps = make_set(kDyadic);
  LeapFrog<2> lf;
  // Dyadic steps that change every step, by up to a factor 4.
  const std::vector<double> dts{1.0 / 64,  1.0 / 32, 3.0 / 128, 1.0 / 128, 1.0 / 16,
                                5.0 / 256, 1.0 / 64, 7.0 / 128, 1.0 / 256, 1.0 / 32};
  double t = 0.0;
  for (std::size_t n = 0; n < 3 * dts.size(); ++n) {
    const double dt = dts[n % dts.size()];
    lf.advance(ps, dt, false);
    t += dt;
    for (std::size_t i = 0; i < kDyadic.size(); ++i) {
      const auto& s = kDyadic[i];
      // Dyadic data: exact, no tolerance (see the file comment for why the scheme is exact).
      ASSERT_EQ(ps.x[i], s.x + s.v * t + s.a * (0.5 * t * t)) << "particle " << i << " step " << n;
      ASSERT_EQ(ps.v[i], s.v + s.a * t) << "particle " << i << " step " << n;
      ASSERT_EQ(ps.v_half[i], s.v + s.a * (t - 0.5 * dt)) << "particle " << i << " step " << n;
    }
  }
}

TEST(LeapFrog, ConstantAccelerationArbitraryDataToRoundOff) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Start> st(5);
  for (auto& s : st)
    for (int k = 0; k < 2; ++k) {
      s.x[k] = u(rng);
      s.v[k] = u(rng);
      s.a[k] = 10.0 * u(rng);
    }
  auto ps = make_set(st);
  LeapFrog<2> lf;
  std::uniform_real_distribution<double> step(0.5e-3, 2e-3);
  double t = 0.0;
  const int steps = 200;
  for (int n = 0; n < steps; ++n) {
    const double dt = step(rng);  // a different, non-dyadic step every time
    lf.advance(ps, dt, false);
    t += dt;
  }
  for (std::size_t i = 0; i < st.size(); ++i) {
    const auto& s = st[i];
    const Vec<2> x = s.x + s.v * t + s.a * (0.5 * t * t);
    const Vec<2> v = s.v + s.a * t;
    for (int k = 0; k < 2; ++k) {
      // No truncation error; round-off of N = 200 accumulated additions: each drift and kick
      // rounds by <= eps/2 of the running value, and a velocity error made at step m is carried
      // by the remaining drifts, so |dx| <~ N eps (|x| + |v| t + |a| t^2) and
      // |dv| <~ N eps (|v| + |a| t). Here t ~ 0.25, |x|, |v| <= ~5.
      const double scale_x = std::abs(s.x[k]) + std::abs(s.v[k]) * t + std::abs(s.a[k]) * t * t;
      const double scale_v = std::abs(s.v[k]) + std::abs(s.a[k]) * t;
      EXPECT_NEAR(ps.x[i][k], x[k], steps * kEps * (scale_x + 1.0)) << "particle " << i;
      EXPECT_NEAR(ps.v[i][k], v[k], steps * kEps * (scale_v + 1.0)) << "particle " << i;
    }
  }
}

TEST(LeapFrog, ConstantDensityRateGrowsDensityLinearly) {
  auto ps = make_set(kDyadic);
  const std::vector<double> drho{3.0, -0.5, 0.0};
  for (std::size_t i = 0; i < drho.size(); ++i)
    ps.drho[i] = drho[i];
  LeapFrog<2> lf;
  double t = 0.0;
  const std::vector<double> dts{1.0 / 64, 1.0 / 32, 3.0 / 128, 1.0 / 128};
  for (int n = 0; n < 40; ++n) {
    const double dt = dts[static_cast<std::size_t>(n) % dts.size()];
    lf.advance(ps, dt, true);
    t += dt;
    for (std::size_t i = 0; i < drho.size(); ++i)
      // Dyadic rates and steps from rho = 1000: every partial sum is representable, so exact.
      ASSERT_EQ(ps.rho[i], 1000.0 + drho[i] * t) << "particle " << i << " step " << n;
  }
}

TEST(LeapFrog, DensityUntouchedWhenNotEvolved) {
  auto ps = make_set(kDyadic);
  for (auto& r : ps.drho)
    r = 5.0;
  LeapFrog<2> lf;
  for (int n = 0; n < 10; ++n)
    lf.advance(ps, 1.0 / 64, false);
  for (std::size_t i = 0; i < ps.size(); ++i)
    EXPECT_EQ(ps.rho[i], 1000.0);
}

TEST(LeapFrog, GhostsAreNotAdvanced) {
  auto ps = make_set(kDyadic);
  // Append one "ghost" after the real particles, with a non-zero rate.
  ps.resize(ps.n_real + 1);
  const std::size_t g = ps.n_real;
  ps.x[g] = Vec<2>{{9.0, 9.0}};
  ps.v_half[g] = ps.v[g] = Vec<2>{{1.0, 1.0}};
  ps.a[g] = Vec<2>{{1.0, 1.0}};
  ps.rho[g] = 1000.0;
  ps.drho[g] = 1.0;
  LeapFrog<2> lf;
  lf.advance(ps, 1.0 / 64, true);
  EXPECT_EQ(ps.x[g], (Vec<2>{{9.0, 9.0}}));
  EXPECT_EQ(ps.v[g], (Vec<2>{{1.0, 1.0}}));
  EXPECT_EQ(ps.v_half[g], (Vec<2>{{1.0, 1.0}}));
  EXPECT_EQ(ps.rho[g], 1000.0);
}

// --- time step ----------------------------------------------------------------------------------

Physics<2> physics(double mu) {
  Physics<2> ph;
  ph.eos.rho0 = 1000.0;
  ph.eos.gamma = 7.0;
  ph.eos.kappa = 1000.0 * 20.0 * 20.0 / 7.0;  // c0 = 20 m/s
  ph.mu = mu;
  ph.gravity = Vec<2>{{0.0, -9.81}};
  return ph;
}

ParticleSet<2> at_rest(const std::vector<double>& h) {
  ParticleSet<2> ps;
  for (std::size_t i = 0; i < h.size(); ++i)
    ps.add_real(static_cast<std::int64_t>(i), Vec<2>{{0.1 * static_cast<double>(i), 0.0}}, Vec<2>{},
                0.01, 1000.0, h[i]);
  return ps;
}

TEST(LeapFrog, CflTimeStepAcousticLimitAtRest) {
  const auto ph = physics(0.0);
  const auto ps = at_rest({0.03, 0.02, 0.025});
  const double c0 = ph.eos.reference_sound_speed();
  // cfl * (h / c0) vs cfl * h / c0: two roundings in a different order, within 4 ulp.
  EXPECT_DOUBLE_EQ(cfl_time_step(ps, ph, 0.25), 0.25 * 0.02 / c0);
  EXPECT_DOUBLE_EQ(cfl_time_step(ps, ph, 0.1), 0.1 * 0.02 / c0);
}

TEST(LeapFrog, CflTimeStepParticleSpeedAddsToSoundSpeed) {
  const auto ph = physics(0.0);
  auto ps = at_rest({0.02, 0.02});
  ps.v[1] = Vec<2>{{3.0, 4.0}};  // |v| = 5
  const double c0 = ph.eos.reference_sound_speed();
  EXPECT_DOUBLE_EQ(cfl_time_step(ps, ph, 0.25), 0.25 * 0.02 / (c0 + 5.0));  // a few roundings
}

TEST(LeapFrog, CflTimeStepViscousLimitCapsTheStep) {
  const auto ps = at_rest({0.03, 0.02});
  const double cfl = 0.25;
  {
    // Small mu: the acoustic limit 0.25 * 0.02 / 20 = 2.5e-4 wins over 0.125 h^2 rho0 / mu = 5.
    const auto ph = physics(1e-2);
    EXPECT_DOUBLE_EQ(cfl_time_step(ps, ph, cfl), cfl * 0.02 / ph.eos.reference_sound_speed());
  }
  {
    // Large mu: 0.125 * 0.02^2 * 1000 / 1000 = 5e-5 < 2.5e-4; uses h_min. Same operations in the
    // same order as the code up to one rounding: 4 ulp.
    const auto ph = physics(1000.0);
    EXPECT_DOUBLE_EQ(cfl_time_step(ps, ph, cfl), 0.125 * 0.02 * 0.02 * 1000.0 / 1000.0);
  }
}

TEST(LeapFrog, CflTimeStepBodyForceLimitCapsTheStep) {
  const auto ph = physics(0.0);
  auto ps = at_rest({0.02, 0.04, 0.03});
  ps.a[1] = Vec<2>{{6.0e4, -8.0e4}};  // |a| = 1e5 on the particle with h = 0.04
  // 0.25 sqrt(0.04 / 1e5) = 1.58e-4 < 0.25 * 0.02 / 20 = 2.5e-4: the force limit of that
  // particle (its own h, not h_min). One sqrt and a couple of roundings: 4 ulp.
  EXPECT_DOUBLE_EQ(cfl_time_step(ps, ph, 0.25), 0.25 * std::sqrt(0.04 / 1.0e5));
  // A small |a| does not bind.
  ps.a[1] = Vec<2>{{0.0, -9.81}};
  EXPECT_DOUBLE_EQ(cfl_time_step(ps, ph, 0.25), 0.25 * 0.02 / ph.eos.reference_sound_speed());
}

TEST(LeapFrog, CflTimeStepGhostsDoNotLimitTheStep) {
  const auto ph = physics(0.0);
  auto ps = at_rest({0.02, 0.02});
  ps.resize(3);  // a ghost with a tiny h and a huge speed
  ps.h[2] = 1e-9;
  ps.v[2] = Vec<2>{{1e6, 0.0}};
  ps.a[2] = Vec<2>{{1e9, 0.0}};
  EXPECT_DOUBLE_EQ(cfl_time_step(ps, ph, 0.25), 0.25 * 0.02 / ph.eos.reference_sound_speed());
}

// A simulation takes the step from the force sweep, block by block as each acceleration is
// finished (sweep_least): it must be cfl_time_step of the accelerations the sweep wrote, to
// the bit (the same operations on each particle and an exact minimum), for every preset. A
// random cloud of a few thousand particles (several blocks of the pass) with random
// velocities, viscous (the viscous limit in play) and not.
TEST(LeapFrog, ForceSweepReturnsTheCflStepOfItsAccelerations) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ParticleSet<2> cloud;
  for (int i = 0; i < 3000; ++i)
    cloud.add_real(i, Vec<2>{{u(rng), u(rng)}}, Vec<2>{{u(rng) - 0.5, u(rng) - 0.5}}, 0.4,
                   1000.0 + 20.0 * u(rng), 0.015);
  for (const double mu : {0.0, 5.0}) {
    auto ph = physics(mu);
    ph.av_alpha = 0.1;
    for (const char* preset : {"standard", "continuity", "csph"}) {
      auto ps = cloud;
      auto scheme = make_scheme<2>(*preset_rows(preset), KernelKind::wendland_c2, ph);
      const StepLimit<2> limit(ph, 0.3);
      double dt = 0.0;
      test::in_cell_order(scheme->support(), ps, static_cast<const BoxWalls<2>*>(nullptr),
                          [&](ParticleSet<2>& s, const SweepContext<2>& ctx, const Halo<2>& halo) {
                            dt = scheme->compute_accelerations(s, ctx, halo, limit);
                          });
      EXPECT_EQ(dt, cfl_time_step(ps, ph, 0.3)) << preset << ", mu " << mu;
      EXPECT_GT(dt, 0.0);
    }
  }
}

}  // namespace
}  // namespace flume
