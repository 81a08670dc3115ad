// The time-step rules of time_step.hpp, by hand: W (3.88)-(3.90) with the pair signal of W
// (3.88), and the viscous limit with LES's eddy viscosity.
#include <gtest/gtest.h>

#include <cmath>

#include "flume/integrators/time_step.hpp"
#include "flume/schemes/registry.hpp"
#include "flume/sim/simulation.hpp"
#include "support/lattice.hpp"
#include "support/rates.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

ParticleSet<2> one_particle(double h, double c, const Vec<2>& v, const Vec<2>& a) {
  ParticleSet<2> ps;
  ps.add_real(0, Vec<2>{{0.0, 0.0}}, v, 0.1, 1000.0, h);
  ps.c[0] = c;
  ps.a[0] = a;
  ps.signal[0] = 0.0;
  ps.nu_t[0] = 0.0;
  return ps;
}

TEST(StepLimit, W388TakesTheLocalSoundSpeedThePairSignalAndTheForce) {
  Physics<2> phys;
  phys.eos.rho0 = 1000.0;
  phys.eos.gamma = 7.0;
  phys.eos.kappa = 1000.0 * 100.0 / 7.0;  // c0 = 10 m/s: W (3.88) ignores it
  const StepLimit<2> limit(phys, 0.3, StepRule::w388);
  auto ps = one_particle(0.01, 12.0, Vec<2>{{3.0, 4.0}}, Vec<2>{{0.0, 0.0}});
  ps.signal[0] = 8.0;
  // dt_c = h / (c_i + s_i) (|v| does not enter), times 0.3.
  EXPECT_DOUBLE_EQ(limit.least(ps, 0, 1), 0.3 * 0.01 / (12.0 + 8.0));
  // dt_F = sqrt(h / |a|), also times 0.3 (W (3.90)), where BL (63)'s rule takes 0.25.
  ps.a[0] = Vec<2>{{3.0e4, 4.0e4}};
  EXPECT_DOUBLE_EQ(limit.least(ps, 0, 1), 0.3 * std::sqrt(0.01 / 5.0e4));
  const StepLimit<2> bl63(phys, 0.3);
  ps.a[0] = Vec<2>{{0.0, 0.0}};
  EXPECT_DOUBLE_EQ(bl63.least(ps, 0, 1), 0.3 * 0.01 / (10.0 + 5.0));
}

TEST(StepLimit, EddyViscosityEntersTheViscousLimit) {
  Physics<2> phys;
  phys.eos.rho0 = 1000.0;
  phys.eos.gamma = 7.0;
  phys.eos.kappa = 1000.0 * 100.0 / 7.0;
  phys.mu = 1e-3;
  phys.les.on = true;
  const StepLimit<2> limit(phys, 0.3);
  auto ps = one_particle(0.01, 10.0, Vec<2>{{0.0, 0.0}}, Vec<2>{{0.0, 0.0}});
  ps.nu_t[0] = 0.5;  // m^2/s: 0.125 h^2 / (nu + nu_t) = 2.5e-5 s < 0.3 h / c0 = 3e-4 s
  EXPECT_DOUBLE_EQ(limit.least(ps, 0, 1), 0.125 * 0.01 * 0.01 * 1000.0 / (1e-3 + 1000.0 * 0.5));
  phys.les.on = false;
  const StepLimit<2> no_les(phys, 0.3);
  EXPECT_DOUBLE_EQ(no_les.least(ps, 0, 1), 0.3 * 0.01 / 10.0);
}

TEST(SignalSpeedW388, PairMaximumByHand) {
  // Three particles in a row: the middle one's signal is the larger of its two pairs'
  // |h u_ij . x_ij| / (|x_ij|^2 + 0.01 h^2); the ends see one pair each (in range).
  const double h = 0.013;
  ParticleSet<2> ps;
  ps.add_real(0, Vec<2>{{0.0, 0.0}}, Vec<2>{{1.0, 0.0}}, 0.1, 1000.0, h);
  ps.add_real(1, Vec<2>{{0.01, 0.002}}, Vec<2>{{-0.5, 0.3}}, 0.1, 1000.0, h);
  ps.add_real(2, Vec<2>{{0.021, 0.0}}, Vec<2>{{0.2, -0.4}}, 0.1, 1000.0, h);
  const auto x = ps;
  test::in_cell_order(2.0, ps, static_cast<const BoxWalls<2>*>(nullptr),
                      [&](ParticleSet<2>& s, const SweepContext<2>& ctx, const Halo<2>&) {
                        signal_speed_w388(ctx.grid, s, 2.0 * h);
                      });
  auto s = [&](std::size_t i, std::size_t j) {
    const Vec<2> xij = x.x[i] - x.x[j];
    return std::abs(h * dot(x.v[i] - x.v[j], xij)) / (norm2(xij) + 0.01 * h * h);
  };
  ASSERT_LT(norm(x.x[0] - x.x[2]), 2.0 * h);  // all three pairs in range
  EXPECT_DOUBLE_EQ(ps.signal[0], std::max(s(0, 1), s(0, 2)));
  EXPECT_DOUBLE_EQ(ps.signal[1], std::max(s(1, 0), s(1, 2)));
  EXPECT_DOUBLE_EQ(ps.signal[2], std::max(s(2, 0), s(2, 1)));
  EXPECT_GT(ps.signal[1], 0.0);
}

TEST(SignalSpeedW388, UniformMotionStepsAtTheSoundSpeed) {
  // A lattice moving as a whole at rho0: u_ij = 0 (no signal) and a = 0 (p = 0), so W (3.88)-
  // (3.90) give 0.3 h / c0, where BL (63) gives 0.3 h / (c0 + |v|).
  const double h = 0.013, c0 = 10.0;
  Physics<2> phys;
  phys.eos.rho0 = 1000.0;
  phys.eos.gamma = 7.0;
  phys.eos.kappa = 1000.0 * c0 * c0 / 7.0;
  for (const auto rule : {StepRule::w388, StepRule::bl63}) {
    auto ps = test::square_lattice(
        7, 0.01, h, 0.0, 1, [](const Vec<2>&) { return 1000.0; },
        [](const Vec<2>&) {
          return Vec<2>{{3.0, 4.0}};
        });
    SimulationConfig<2> config;
    config.step_rule = rule;
    Simulation<2> sim(ps, test::open_box<2>(-1.0, 1.0),
                      make_scheme<2>(*preset_rows("wsph"), KernelKind::wendland_c2, phys), phys,
                      config);
    sim.step(1.0);
    EXPECT_DOUBLE_EQ(sim.last_dt(), rule == StepRule::w388 ? 0.3 * h / c0 : 0.3 * h / (c0 + 5.0));
  }
}

}  // namespace
}  // namespace flume
