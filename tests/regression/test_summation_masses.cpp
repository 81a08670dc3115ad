// particles.mass = "summation" (src/flume/case/summation_masses.hpp): m_a = rho_a / sum_b
// W_ab(h_a), checked against a brute-force sum, and what it is for: BL 5.2's random drop with
// standard SPH (the summation density BL (1)) within BL's 2 % of the exact b.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "flume/case/build_simulation.hpp"
#include "flume/case/case_reader.hpp"
#include "flume/case/summation_masses.hpp"
#include "flume/core/error.hpp"
#include "flume/kernels/cubic_spline.hpp"
#include "flume/kernels/wendland_c2.hpp"
#include "flume/theory/elliptical_drop.hpp"
#include "flume/validation/bundled_cases.hpp"

namespace flume {
namespace {

// A random cloud whose particles have two smoothing lengths and two densities, so that a sum
// taken with h_b instead of h_a, or a density not a's own, shows.
template <int D>
ParticleSet<D> cloud(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ParticleSet<D> ps;
  ps.reserve(n);
  for (std::size_t a = 0; a < n; ++a) {
    Vec<D> x;
    for (int k = 0; k < D; ++k)
      x[k] = u(rng);
    const double h = a % 2 ? 0.08 : 0.13;
    const double rho = a % 3 ? 1000.0 : 1250.0;
    ps.add_real(static_cast<std::int64_t>(a), x, Vec<D>{}, 1.0, rho, h);
  }
  return ps;
}

// sum_b m_a W(|x_a - x_b|, h_a) over all b, by brute force: rho_a to round-off (the sum of a
// few dozen positive terms: 1e-13 relative).
template <int D, class Kernel>
void expect_summation_gives_density(std::size_t n) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const ParticleSet<D> ps = cloud<D>(n, seed);
    const std::vector<double> m = summation_masses<D, Kernel>(ps);
    ASSERT_EQ(m.size(), ps.n_real);
    for (std::size_t a = 0; a < ps.n_real; ++a) {
      double sum = 0.0;
      for (std::size_t b = 0; b < ps.n_real; ++b)
        sum += Kernel::w(norm(ps.x[a] - ps.x[b]), ps.h[a]);
      EXPECT_NEAR(m[a] * sum / ps.rho[a], 1.0, 1e-13) << "particle " << a << ", seed " << seed;
    }
  }
}

TEST(SummationMasses, GiveEachParticleItsDensity2D) {
  expect_summation_gives_density<2, CubicSpline<2>>(600);
  expect_summation_gives_density<2, WendlandC2<2>>(600);
}

TEST(SummationMasses, GiveEachParticleItsDensity3D) {
  expect_summation_gives_density<3, CubicSpline<3>>(800);
}

TEST(SummationMasses, RefusedBesideAWall) {
  try {
    read_case(bundled_case("dam_break"), {"particles.mass=\"summation\""});
    FAIL() << "accepted particles.mass = summation in a walled tank";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("particles.mass"), std::string::npos) << e.what();
  }
}

// b of the drop from the mass-weighted second moment along y, relative to the start (the
// probe's method, probes/semi_axes.hpp, written again here).
double second_moment_y(const ParticleSet<2>& ps) {
  double m = 0.0, my = 0.0, myy = 0.0;
  for (std::size_t a = 0; a < ps.n_real; ++a) {
    m += ps.m[a];
    my += ps.m[a] * ps.x[a][1];
    myy += ps.m[a] * ps.x[a][1] * ps.x[a][1];
  }
  const double mean = my / m;
  return myy / m - mean * mean;
}

// The largest |b / b_exact - 1| over the run, or its value at the end.
double drop_b_error(const std::string& file, const std::vector<std::string>& sets,
                    bool largest = false) {
  const CaseSpec spec = read_case(bundled_case(file), sets);
  Simulation<2> sim = build_simulation<2>(spec);
  const double start = second_moment_y(sim.particles());
  double worst = 0.0, error = 0.0;
  while (sim.time() < spec.end_time - 1e-12) {
    sim.step(spec.end_time - sim.time());
    const double b = std::sqrt(second_moment_y(sim.particles()) / start);
    error = b / elliptical_drop_exact(100.0, 1.0, sim.time()).b - 1.0;
    worst = std::max(worst, std::abs(error));
  }
  return largest ? worst : error;
}

// The random drop's standard variant (its case file): h = 1.3 dx, where CSPH there takes 2.0 dx.
std::vector<std::string> standard_with(const std::string& mass) {
  return {"scheme.preset=\"standard\"", "particles.mass=\"" + mass + "\"", "scheme.h_over_dx=1.3",
          "fluid_blocks[0].initial_pressure=\"none\""};
}

// BL 5.2: standard SPH within 2 % of the exact b at t = 0.008 s (BL Table 1: 2.02 against
// 2.00). Measured (uniform start): +0.30 % with the summation masses; +31 % with m = rho V, whose
// surface particles start at ~60 % of rho0, in tension, and tear the rim outwards.
TEST(SummationMasses, StandardRandomDropWithinBonetLoksTwoPercent) {
  EXPECT_LT(std::abs(drop_b_error("elliptical_drop_random", standard_with("summation"))), 0.02);
  EXPECT_GT(std::abs(drop_b_error("elliptical_drop_random", standard_with("volume"))), 0.05);
}

// CSPH on the lattice drop: started at uniform density, b rings about the exact solution
// (0.15 % at t = 1 ms: the acoustic start-up, R / c0 = 0.7 ms); started at the pressure of its
// flow it follows it to 0.007 % over the run. Bounds: 0.02 % (three times the measured) and
// 0.1 % (two thirds of the measured ringing).
TEST(DropStart, AtThePressureOfItsFlowNoStartUpRinging) {
  EXPECT_LT(drop_b_error("elliptical_drop", {"fluid_blocks[0].initial_pressure=\"velocity_field\""},
                         true),
            2e-4);
  EXPECT_GT(drop_b_error("elliptical_drop", {"fluid_blocks[0].initial_pressure=\"none\""}, true),
            1e-3);
}

TEST(DropStart, RefusedWhereTheFlowHasNoSuchPressure) {
  const auto error = [](const std::vector<std::string>& sets) {
    try {
      read_case(bundled_case("elliptical_drop"), sets);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string on = "fluid_blocks[0].initial_pressure=\"velocity_field\"";
  EXPECT_NE(error({on, "fluid_blocks[0].shape=\"box\""}).find("initial_pressure"),
            std::string::npos);
  EXPECT_NE(error({on, "fluid_blocks[0].velocity_gradient=[-100.0, 0.0, 0.0, 50.0]"})
                .find("initial_pressure"),
            std::string::npos);
  EXPECT_NE(error({on, "fluid_blocks[0].velocity_gradient=[-100.0, 10.0, 0.0, 100.0]"})
                .find("initial_pressure"),
            std::string::npos);
  EXPECT_TRUE(error({on}).empty());
}

}  // namespace
}  // namespace flume
