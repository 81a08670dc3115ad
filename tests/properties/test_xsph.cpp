// XSPH, W (6.6): by hand on a pair through a leap-frog step and a Runge-Kutta step, and its
// property on a cloud: the mass-weighted drift correction sums to zero (the centre of mass moves
// with the mean velocity).
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "flume/schemes/registry.hpp"
#include "flume/sim/simulation.hpp"
#include "support/lattice.hpp"
#include "support/rates.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

constexpr double kRho0 = 1000.0, kC0 = 10.0, kH = 0.013;

Physics<2> water() {
  Physics<2> phys;
  phys.eos.rho0 = kRho0;
  phys.eos.gamma = 7.0;
  phys.eos.kappa = kRho0 * kC0 * kC0 / 7.0;
  return phys;
}

// The particle of the simulation with identity id.
std::size_t by_id(const ParticleSet<2>& ps, std::int64_t id) {
  for (std::size_t i = 0; i < ps.n_real; ++i)
    if (ps.id[i] == id) return i;
  return ps.n_real;
}

// Two particles at rho0 (p = 0) with different velocities, unequal masses.
ParticleSet<2> pair_at_rest_density() {
  ParticleSet<2> ps;
  ps.add_real(0, Vec<2>{{0.0, 0.0}}, Vec<2>{{0.5, 0.1}}, 0.10, kRho0, kH);
  ps.add_real(1, Vec<2>{{0.009, 0.004}}, Vec<2>{{-0.3, 0.2}}, 0.12, kRho0, kH);
  return ps;
}

// One step of dt with XSPH's eps, continuity preset, open box.
Simulation<2> one_step(const ParticleSet<2>& ps, double eps, double dt, Integrator integrator) {
  const auto phys = water();
  SimulationConfig<2> config;
  config.fixed_dt = dt;
  config.xsph = eps;
  config.integrator = integrator;
  Simulation<2> sim(ps, test::open_box<2>(-1.0, 1.0),
                    make_scheme<2>(*preset_rows("continuity"), KernelKind::wendland_c2, phys), phys,
                    config);
  sim.step(1.0);
  return sim;
}

TEST(XsphW66, LeapFrogStepOfAPairByHand) {
  // Two particles at rho0 (p = 0: no force, so v^{1/2} = v^0 and the first half-kick adds
  // nothing): x^1 = x^0 + dt (v_a + eps m_b / rho_bar (v_b - v_a) W_ab), rho_bar = (rho_a +
  // rho_b)/2 (the continuity density is advanced in the same step: rho^1 = rho0 + dt drho, not
  // yet seen by the drift). Round-off: x ~ 1e-2 m, the XSPH part of the move ~ 1e-8 m.
  const double eps = 0.5, dt = 1e-4;
  const auto x0 = pair_at_rest_density();
  const Simulation<2> sim = one_step(x0, eps, dt, Integrator::leap_frog);
  const double w = test::wendland_w(norm(x0.x[0] - x0.x[1]), kH);
  for (std::int64_t a = 0; a < 2; ++a) {
    const auto b = 1 - a;
    const Vec<2> xsph = (x0.v[b] - x0.v[a]) * (eps * x0.m[b] / kRho0 * w);
    const Vec<2> want = x0.x[a] + (x0.v[a] + xsph) * dt;
    const auto& got = sim.particles().x[by_id(sim.particles(), a)];
    EXPECT_NEAR(got[0], want[0], 1e-17) << a;
    EXPECT_NEAR(got[1], want[1], 1e-17) << a;
    // The correction is a visible share of the move (a factor or sign of it would show).
    EXPECT_GT(norm(xsph) * dt, 1e3 * 1e-17);
  }
}

TEST(XsphW66, MidpointRungeKuttaStepOfAPairByHand) {
  // W (3.85)-(3.87) with the drift velocity U = u + xsph(u): x* = x + (dt/2) U(x^n, u^n),
  // x^{n+1} = x^n + dt U(x*, u*). The pair starts at rho0 (p = 0, no force), so u* = u^n
  // exactly; the stage's densities rho* = rho0 + (dt/2) drho (BL (4)) enter its rho_bar.
  const double eps = 0.5, dt = 1e-4;
  const auto x0 = pair_at_rest_density();
  const Simulation<2> sim = one_step(x0, eps, dt, Integrator::runge_kutta);
  auto U = [&](const Vec<2>& xa, const Vec<2>& xb, std::size_t a, double rho_a, double rho_b) {
    const std::size_t b = 1 - a;
    const double w = test::wendland_w(norm(xa - xb), kH);
    return x0.v[a] + (x0.v[b] - x0.v[a]) * (eps * x0.m[b] * 2.0 / (rho_a + rho_b) * w);
  };
  // The stage densities (continuity, BL (4)): rho* = rho0 + (dt/2) drho, drho_a = m_b (v_a -
  // v_b) . grad_a W_ab; they enter rho_bar of the stage's XSPH.
  const Vec<2> g = test::wendland_grad(x0.x[0], x0.x[1], kH);
  const double drho0 = x0.m[1] * dot(x0.v[0] - x0.v[1], g);
  const double drho1 = x0.m[0] * dot(x0.v[1] - x0.v[0], g * -1.0);
  const double r0 = kRho0 + 0.5 * dt * drho0, r1 = kRho0 + 0.5 * dt * drho1;
  const Vec<2> s0 = x0.x[0] + U(x0.x[0], x0.x[1], 0, kRho0, kRho0) * (0.5 * dt);
  const Vec<2> s1 = x0.x[1] + U(x0.x[1], x0.x[0], 1, kRho0, kRho0) * (0.5 * dt);
  const Vec<2> want[2] = {x0.x[0] + U(s0, s1, 0, r0, r1) * dt, x0.x[1] + U(s1, s0, 1, r1, r0) * dt};
  for (std::int64_t a = 0; a < 2; ++a) {
    const auto& got = sim.particles().x[by_id(sim.particles(), a)];
    // W (3.87) rounds twice (2 x** - x^n): a few ulp of x ~ 1e-2 m.
    EXPECT_NEAR(got[0], want[a][0], 1e-16) << a;
    EXPECT_NEAR(got[1], want[a][1], 1e-16) << a;
  }
}

TEST(XsphW66, MassWeightedCorrectionSumsToZero) {
  // sum_a m_a xsph_a = eps sum_pairs (m_a m_b / rho_bar) W ((v_b - v_a) + (v_a - v_b)) = 0: the
  // pair shares are opposite to the last bit, so the sum is round-off of ~|xsph| m n.
  std::mt19937_64 gen(4);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  auto ps = test::square_lattice(
      11, 0.01, kH, 0.25, 7, [&](const Vec<2>&) { return kRho0 * (1.0 + 0.01 * u(gen)); },
      [&](const Vec<2>&) {
        return Vec<2>{{u(gen), u(gen)}};
      });
  const auto phys = water();
  const auto scheme = make_scheme<2>(*preset_rows("continuity"), KernelKind::wendland_c2, phys);
  test::in_cell_order(scheme->support(), ps, static_cast<const BoxWalls<2>*>(nullptr),
                      [&](ParticleSet<2>& s, const SweepContext<2>& ctx, const Halo<2>& halo) {
                        scheme->xsph(s, ctx, halo, s.v, 0.5);
                      });
  Vec<2> total{}, size{};
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    total += ps.xsph[i] * ps.m[i];
    size += Vec<2>{{std::abs(ps.xsph[i][0]), std::abs(ps.xsph[i][1])}} * ps.m[i];
  }
  ASSERT_GT(size[0], 0.0);
  EXPECT_LT(std::abs(total[0]), 1e-14 * size[0]);
  EXPECT_LT(std::abs(total[1]), 1e-14 * size[1]);
}

}  // namespace
}  // namespace flume
