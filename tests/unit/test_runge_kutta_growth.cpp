// How the two Runge-Kutta steps of W 3.4 (src/flume/integrators/runge_kutta.hpp) treat an
// undamped oscillation, x'' = -omega^2 x: why LES-SPH, which runs without artificial viscosity,
// needs a smaller step than W's 5e-5 s in the wave tanks (cases/solitary_wave.toml).
// On (omega x, u) one step of the midpoint W (3.85)-(3.87) is
//   [[1 - theta^2/2, theta], [-theta, 1 - theta^2/2]],   theta = omega dt,
// and so is one step of W (3.92) (x^{n+1} = x^n + dt u^n - (dt^2/2) omega^2 x^n, u^{n+1} =
// u^n - dt omega^2 (x^n + (dt/2) u^n)): a rotation scaled by sqrt(1 + theta^4/4). The energy
// omega^2 x^2 + u^2 of every state grows by 1 + theta^4/4 each step, exactly: a growth rate in
// time of about omega^4 dt^3 / 8, eight times smaller at half the step. Leap-frog (symplectic)
// keeps it bounded instead.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/core/vec.hpp"
#include "flume/integrators/runge_kutta.hpp"

namespace flume {
namespace {

// Particles as independent oscillators about the origin, each with its own starting state.
ParticleSet<2> oscillators(std::size_t n) {
  ParticleSet<2> ps;
  ps.optional = kFieldStepStart;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i + 1);
    ps.add_real(static_cast<std::int64_t>(i), Vec<2>{{0.01 * s, -0.02}}, Vec<2>{{0.3, 0.1 * s}},
                0.01, 1000.0, 0.012);
  }
  ps.resize(ps.size());
  return ps;
}

// `steps` steps of dt of x'' = -omega[i]^2 x for each particle i.
void oscillate(ParticleSet<2>& ps, RungeKuttaKind kind, const std::vector<double>& omega, double dt,
               int steps) {
  const auto rates = [&] {
    for (std::size_t i = 0; i < ps.n_real; ++i)
      ps.a[i] = ps.x[i] * (-omega[i] * omega[i]);
  };
  const RungeKutta<2> rk(kind, EvolvedFields{});
  const auto none = [](std::size_t, std::size_t) { return 0L; };
  for (int n = 0; n < steps; ++n) {
    rates();
    rk.to_stage(ps, dt, 0L, none);
    rates();
    rk.to_end(ps, dt, 0L, none);
  }
}

double energy(const Vec<2>& x, const Vec<2>& u, double omega) {
  return omega * omega * norm2(x) + norm2(u);
}

// After N steps the energy is (1 + theta^4/4)^N of the start's for both steps and every
// theta. Tolerance: each step rounds a few times at 1e-16 relative, so 200 steps stay within
// 1e-12; the growth tested is 1.3 (theta = 0.35, W's Courant number in the tanks) to 10^5
// (theta = 1.2). A step missing a factor 1/2 (a first-order Euler stage) changes the factor at
// theta^2, thousands of times the tolerance.
TEST(RungeKuttaGrowth, UndampedOscillationGrowsByOnePlusThetaToTheFourthOverFour) {
  const double dt = 5e-5;
  const std::vector<double> theta{0.35, 0.7, 1.2};
  std::vector<double> omega;
  for (const double t : theta)
    omega.push_back(t / dt);
  const int steps = 200;
  for (const auto kind : {RungeKuttaKind::midpoint, RungeKuttaKind::modified}) {
    const ParticleSet<2> start = oscillators(omega.size());
    ParticleSet<2> end = start;
    oscillate(end, kind, omega, dt, steps);
    for (std::size_t i = 0; i < omega.size(); ++i) {
      const double t4 = std::pow(theta[i], 4);
      const double expected = std::pow(1.0 + t4 / 4.0, steps);
      const double ratio =
          energy(end.x[i], end.v[i], omega[i]) / energy(start.x[i], start.v[i], omega[i]);
      EXPECT_NEAR(ratio / expected, 1.0, 1e-12) << "theta " << theta[i];
    }
  }
}

// The consequence for a time step: over a fixed time T, halving dt at fixed omega divides the
// log of the growth by 8 (to O(theta^4)): the noise LES-SPH's long tank shows at 5e-5 s grows
// eight times slower at 2.5e-5 s. Checked on the integrator: theta = 0.35 and 0.175 over the
// same time; the ratio of logs is 8 up to the O(theta^4) terms of ln(1 + theta^4/4) (0.2 % at
// theta = 0.35): within 1 %.
TEST(RungeKuttaGrowth, HalvingTheStepDividesTheGrowthRateByEight) {
  const double omega = 0.35 / 5e-5;
  for (const auto kind : {RungeKuttaKind::midpoint, RungeKuttaKind::modified}) {
    const auto log_growth = [&](double dt, int steps) {
      const ParticleSet<2> start = oscillators(1);
      ParticleSet<2> end = start;
      oscillate(end, kind, {omega}, dt, steps);
      return std::log(energy(end.x[0], end.v[0], omega) / energy(start.x[0], start.v[0], omega));
    };
    const double coarse = log_growth(5e-5, 400), fine = log_growth(2.5e-5, 800);
    EXPECT_NEAR(coarse / fine, 8.0, 0.08);
  }
}

}  // namespace
}  // namespace flume
