// The thesis's schemes (W 3.2, 3.3, 4.1: presets sph-euler, wsph, rsph) for a gas: the size of
// each equation against an independent computation (the density, energy and smoothing-length
// rates of a linear velocity field; the energy the artificial viscosity turns into heat), the
// energy balance of each force with its energy equation (W (3.61)), R-SPH's renormalized
// gradient on a random cloud, and the Runge-Kutta steps W (3.85)-(3.87), (3.92).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "flume/kernels/cubic_spline.hpp"
#include "flume/schemes/registry.hpp"
#include "flume/sim/simulation.hpp"
#include "support/lattice.hpp"
#include "support/rates.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

constexpr double kDx = 0.01, kH = 1.2 * kDx, kGamma = 1.4;
using Kernel = CubicSpline<2>;

Physics<2> gas(double alpha = 0.0, double beta = 0.0) {
  Physics<2> phys;
  phys.eos.kind = EosKind::ideal_gas;
  phys.eos.gamma = kGamma;
  phys.eos.rho0 = 1.0;
  phys.gravity = Vec<2>{};
  phys.av_alpha = alpha;
  phys.av_beta = beta;
  return phys;
}

std::unique_ptr<Scheme<2>> scheme(const std::string& preset, const Physics<2>& phys,
                                  bool evolving_h = false) {
  SchemeRows rows = *preset_rows(preset);
  rows.smoothing_length = evolving_h ? "evolving" : "fixed";
  return make_scheme<2>(rows, KernelKind::cubic_spline, phys);
}

// Allocates the fields of the scheme (as a Simulation does) and sets every e to `e`.
void prepare(ParticleSet<2>& ps, const Scheme<2>& s, double e) {
  ps.use_only(s.fields());
  for (auto& v : ps.e)
    v = e;
}

// sum_b V_b (u_b - u_a) . grad_a W_ab by brute force over all particles, V = m/rho: the SPH
// divergence at a, computed here independently of the sweep.
double divergence(const ParticleSet<2>& ps, std::size_t a) {
  double d = 0.0;
  for (std::size_t b = 0; b < ps.n_real; ++b) {
    if (b == a) continue;
    const Vec<2> xab = ps.x[a] - ps.x[b];
    const double r = norm(xab), h = 0.5 * (ps.h[a] + ps.h[b]);
    const Vec<2> gw = xab * (Kernel::dwdr(r, h) / r);
    d += ps.m[b] / ps.rho[b] * dot(ps.v[b] - ps.v[a], gw);
  }
  return d;
}

const Mat<2> kA = [] {
  Mat<2> a;
  a(0, 0) = -3.0;
  a(0, 1) = 1.5;
  a(1, 0) = -0.5;
  a(1, 1) = -2.0;
  return a;
}();

ParticleSet<2> uniform_gas_lattice(int n, double jitter) {
  return test::square_lattice(
      n, kDx, kH, jitter, 7, [](const Vec<2>&) { return 1.0; },
      [](const Vec<2>& x) { return kA * x; });
}

class GasScheme : public ::testing::TestWithParam<const char*> {};

// Uniform rho and e, velocity u = A x: p is uniform, so W (3.50) and the corrected W (3.79) both
// reduce to d rho_i/dt = -rho_i div u with the scheme's divergence, and W (3.52), (3.81) to
// d e_i/dt = -(p/rho) div u (the first law), with div u the SPH divergence (computed here by
// brute force; for R-SPH on the perfect lattice B_ij = B_i, so its divergence is exactly
// tr A). Tolerance: ~50-term sums of O(1) terms, 1e-12 of the largest rate; a halved term, a
// flipped sign or a missing p_j/p_i is off by O(1).
TEST_P(GasScheme, RatesOfALinearFieldAreTheFirstLaw) {
  const std::string preset = GetParam();
  const Physics<2> phys = gas();
  const auto s = scheme(preset, phys, true);
  auto ps = uniform_gas_lattice(21, 0.0);
  const double e = 2.5, p = (kGamma - 1.0) * 1.0 * e;
  prepare(ps, *s, e);
  const auto before = ps;
  test::compute_rates(*s, ps);
  // Within 4.5 dx of the centre of the 21 x 21 lattice (edge at 10 dx): i and every neighbour
  // j (2.4 dx away) have the full lattice neighbourhood, so B_j = B_i for R-SPH.
  const auto interior = test::within(ps, 4.5 * kDx);
  ASSERT_GE(interior.size(), 9u);
  for (const auto i : interior) {
    const double div = preset == "rsph" ? kA(0, 0) + kA(1, 1) : divergence(before, i);
    EXPECT_NEAR(ps.drho[i], -1.0 * div, 1e-12 * 5.0) << preset << " " << i;
    EXPECT_NEAR(ps.de[i], -p / 1.0 * div, 1e-12 * 5.0 * p) << preset << " " << i;
    // W (2.22): d eps/dt = -(eps / (n rho)) d rho/dt = (eps / 2) div u in 2D.
    EXPECT_NEAR(ps.dh[i], 0.5 * kH * div, 1e-12 * 5.0 * kH) << preset << " " << i;
    // Uniform pressure: no force (the interior sums of grad W vanish by symmetry), to the
    // round-off of p/rho grad W sums: |grad W| ~ 1/h^3 * dx^2 ~ 1e2 per term.
    EXPECT_LT(norm(ps.a[i]), 1e-10 * p / kDx) << preset << " " << i;
  }
  // The continuum values are within 1 % of these (lattice consistency at h = 1.2 dx): the
  // brute-force divergence must be near tr A = -5, or the reference itself is wrong.
  EXPECT_NEAR(divergence(before, interior.front()), -5.0, 0.05);
}

// The energy of the semi-discrete system, sum_i m_i (e_i + u_i^2/2), is kept by each force
// with its energy equation (W (3.61), W 3.3.2): sum_i m_i (de_i + u_i . a_i) = 0, artificial
// viscosity included. On a jittered cloud with random pressures and velocities, no walls, no
// body force. Tolerance: round-off of sums of ~1e4 terms of size m |u| |a| (1e-12 relative to
// sum m |u . a|); a halved Pi in either equation, a dropped p_i/rho_i^2 or a wrong 1/2 in W
// (3.52) breaks the balance at O(1) (the viscous heating alone is ~10 % of the exchanges).
TEST_P(GasScheme, ForceAndEnergyEquationKeepTotalEnergy) {
  const std::string preset = GetParam();
  const Physics<2> phys = gas(1.0, 2.0);
  const auto s = scheme(preset, phys);
  auto ps = uniform_gas_lattice(13, 0.2);
  prepare(ps, *s, 1.0);
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    ps.e[i] = 1.0 + 0.5 * u(gen);
    ps.rho[i] *= 1.0 + 0.3 * u(gen);
    ps.v[i] = Vec<2>{{u(gen), u(gen)}};
    ps.v_half[i] = ps.v[i];  // the energy equation's velocity: the same field (as in RK)
  }
  test::compute_rates(*s, ps);
  double balance = 0.0, heat = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    balance += ps.m[i] * (ps.de[i] + dot(ps.v[i], ps.a[i]));
    heat += ps.m[i] * ps.de[i];
    scale += ps.m[i] * std::abs(dot(ps.v[i], ps.a[i]));
  }
  EXPECT_LT(std::abs(balance), 1e-12 * scale) << preset;
  EXPECT_GT(std::abs(heat), 1e-3 * scale) << preset << ": the test must exchange energy";
}

// Two particles approaching head-on at equal pressure: the energy each gains is the pair's
// pressure work plus its share of the viscous heating, by hand from W (3.18) and the scheme's
// energy equation (W (3.52): 1/2 (P_i + P_j + Pi/rho_bar^2) m_j u_ij . grad W; W (3.81):
// m_j (p_j + Pi/2)/(rho_i rho_j) u_ij . grad W). Exact to round-off (few-term sums).
TEST_P(GasScheme, ApproachingPairHeatsAsTheArtificialViscosityGives) {
  const std::string preset = GetParam();
  if (preset == std::string("rsph")) GTEST_SKIP() << "B_i of two particles is singular";
  const double alpha = 1.0, beta = 2.0;
  const Physics<2> phys = gas(alpha, beta);
  const auto s = scheme(preset, phys);
  ParticleSet<2> ps;
  const double r = 0.8 * kDx, speed = 0.7, e = 2.0, rho = 1.0, m = rho * kDx * kDx;
  ps.add_real(0, Vec<2>{{0.0, 0.0}}, Vec<2>{{speed, 0.0}}, m, rho, kH);
  ps.add_real(1, Vec<2>{{r, 0.0}}, Vec<2>{{-speed, 0.0}}, m, rho, kH);
  prepare(ps, *s, e);
  test::compute_rates(*s, ps);
  const double p = (kGamma - 1.0) * rho * e, c = std::sqrt(kGamma * p / rho);
  // Pi_01 (pressure units): mu = h u.x / (r^2 + 0.01 h^2), u.x = (u_0 - u_1).(x_0 - x_1) < 0.
  const double ux = (2.0 * speed) * (-r);
  const double mu = kH * ux / (r * r + 0.01 * kH * kH);
  const double pi = -alpha * c * rho * mu + beta * rho * mu * mu;
  // (u_1 - u_0) . grad_0 W(x_0 - x_1) = (-2 speed) (-r) W'(r) / r... with x_01 = -r e_x.
  const double dwdr = Kernel::dwdr(r, kH);
  const double u_gradw = (-2.0 * speed) * (-dwdr);  // grad_0 W = (x_0 - x_1)/r W' = -W' e_x
  const double de = preset == std::string("sph-euler")
                        ? -0.5 * m * (2.0 * p / (rho * rho) + pi / (rho * rho)) * u_gradw
                        : -m / (rho * rho) * (p + 0.5 * pi) * u_gradw;
  ASSERT_GT(pi, 0.0);
  EXPECT_NEAR(ps.de[0], de, 1e-13 * std::abs(de)) << preset;
  EXPECT_NEAR(ps.de[1], de, 1e-13 * std::abs(de)) << preset;
}

INSTANTIATE_TEST_SUITE_P(Presets, GasScheme, ::testing::Values("sph-euler", "wsph", "rsph"));

// R-SPH's renormalized derivative W (4.9) with B_i of W (4.11) reproduces the gradient of any
// linear field exactly on any cloud: sum_j omega_j (f_j - f_i) B_i grad_i psi_ij = grad f. B_i
// is what the rsph scheme leaves in ps.L. Round-off bound: ~30 terms of size |grad f|.
TEST(RenormalizedGradient, ExactForLinearFieldsOnARandomCloud) {
  const Physics<2> phys = gas();
  const auto s = scheme("rsph", phys);
  auto ps = uniform_gas_lattice(13, 0.35);
  prepare(ps, *s, 1.0);
  const auto before = ps;
  test::compute_rates(*s, ps);
  const Vec<2> grad_f{{2.0, -7.0}};
  const auto f = [&](const Vec<2>& x) { return dot(grad_f, x) + 0.3; };
  const auto interior = test::within(ps, 6 * kDx - 3.0 * kDx);
  ASSERT_GE(interior.size(), 9u);
  for (const auto i : interior) {
    Vec<2> g;
    for (std::size_t j = 0; j < ps.n_real; ++j) {
      if (j == i) continue;
      const Vec<2> xij = before.x[i] - before.x[j];
      const double rr = norm(xij);
      const Vec<2> gw = xij * (Kernel::dwdr(rr, kH) / rr);
      g += (ps.L[i] * gw) * (before.m[j] / before.rho[j] * (f(before.x[j]) - f(before.x[i])));
    }
    EXPECT_NEAR(g[0], grad_f[0], 1e-11 * norm(grad_f)) << i;
    EXPECT_NEAR(g[1], grad_f[1], 1e-11 * norm(grad_f)) << i;
  }
}

// A gas cloud with random energies and velocities in an open box, integrated by the two Runge-Kutta
// steps: W (3.92) keeps total linear momentum to round-off (its new velocity is u^n plus dt
// times antisymmetric pair forces); so does the midpoint step, whose 2 Phi** - Phi^n rounds
// twice. Bound: 1e-13 of sum m |u| after 20 steps (each step adds ~1e-16 relative).
TEST(RungeKutta, BothStepsKeepLinearMomentum) {
  for (const auto integrator : {Integrator::runge_kutta, Integrator::modified_runge_kutta}) {
    const Physics<2> phys = gas(1.0, 2.0);
    auto ps = uniform_gas_lattice(11, 0.2);
    ps.optional = kFieldEnergy;
    ps.resize(ps.size());
    std::mt19937_64 gen(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Vec<2> p0;
    double scale = 0.0;
    for (std::size_t i = 0; i < ps.n_real; ++i) {
      ps.e[i] = 1.0 + 0.5 * u(gen);
      ps.v[i] = ps.v_half[i] = Vec<2>{{0.1 * u(gen), 0.1 * u(gen)}};
      p0 += ps.v[i] * ps.m[i];
      scale += ps.m[i] * norm(ps.v[i]);
    }
    SimulationConfig<2> config;
    config.integrator = integrator;
    // A fixed step, a tenth of the CFL step: the cloud's edge expands into vacuum.
    config.fixed_dt = 2e-4;
    Simulation<2> sim(ps, test::open_box<2>(-1.0, 1.0), scheme("wsph", phys), phys, config);
    for (int k = 0; k < 20; ++k)
      sim.step(1.0);
    Vec<2> p1;
    for (std::size_t i = 0; i < sim.particles().n_real; ++i)
      p1 += sim.particles().v[i] * sim.particles().m[i];
    EXPECT_LT(norm(p1 - p0), 1e-13 * scale);
    EXPECT_GT(sim.time(), 0.0);
  }
}

// Both Runge-Kutta steps are second order: a constant-acceleration free fall (exact for them)
// and the order of the error on a pressure-driven expansion, from the step-halving ratio of the
// final positions against a 4x finer run. Second order gives ratio ~4; first order 2.
TEST(RungeKutta, SecondOrderOnAnExpandingGas) {
  for (const auto integrator : {Integrator::runge_kutta, Integrator::modified_runge_kutta}) {
    const auto run = [&](double dt) {
      const Physics<2> phys = gas(0.5, 1.0);
      auto ps = uniform_gas_lattice(9, 0.1);
      ps.optional = kFieldEnergy;
      ps.resize(ps.size());
      for (std::size_t i = 0; i < ps.n_real; ++i)
        ps.e[i] = 1.0 + 20.0 * std::exp(-norm2(ps.x[i]) / (4.0 * kDx * kDx));
      SimulationConfig<2> config;
      config.integrator = integrator;
      config.fixed_dt = dt;
      Simulation<2> sim(ps, test::open_box<2>(-1.0, 1.0), scheme("wsph", phys), phys, config);
      const int steps = static_cast<int>(std::lround(4e-3 / dt));
      for (int k = 0; k < steps; ++k)
        sim.step(1.0);
      return sim.particles();
    };
    const auto ref = run(1.25e-5), coarse = run(1e-4), fine = run(5e-5);
    double ec = 0.0, ef = 0.0;
    for (std::size_t i = 0; i < ref.n_real; ++i) {
      ec = std::max(ec, norm(coarse.x[i] - ref.x[i]));
      ef = std::max(ef, norm(fine.x[i] - ref.x[i]));
    }
    ASSERT_GT(ef, 0.0);
    EXPECT_GT(ec / ef, 3.0) << static_cast<int>(integrator);
    EXPECT_LT(ec / ef, 5.5) << static_cast<int>(integrator);
  }
}

}  // namespace
}  // namespace flume
