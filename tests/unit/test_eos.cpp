// Unit tests of the Tait equation of state (src/flume/equations/eos_tait.hpp):
//   p = kappa [ (rho / rho0)^gamma - 1 ],  compression positive,
// its sound speed, its stored elastic energy and its hydrostatic profile.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "flume/equations/eos_tait.hpp"

namespace flume {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// A water-like fluid: c0 = 20 m/s (10 sqrt(g H) for a 0.4 m column), kappa = rho0 c0^2 / gamma.
TaitEos water(double gamma = 7.0) {
  TaitEos e;
  e.rho0 = 1000.0;
  e.gamma = gamma;
  e.kappa = e.rho0 * 20.0 * 20.0 / gamma;
  return e;
}

TEST(TaitEos, ZeroPressureAtReferenceDensity) {
  for (const double gamma : {1.0, 1.4, 7.0}) {
    const TaitEos e = water(gamma);
    // (rho0 / rho0)^gamma = pow(1, gamma) = 1 exactly, so exactly 0.
    EXPECT_EQ(e.pressure(e.rho0), 0.0) << "gamma " << gamma;
  }
}

TEST(TaitEos, CompressionPositiveTensionNegative) {
  const TaitEos e = water();
  EXPECT_GT(e.pressure(1001.0), 0.0);
  EXPECT_GT(e.pressure(1100.0), e.pressure(1001.0));  // monotone
  EXPECT_LT(e.pressure(999.0), 0.0);
  // The linearised value kappa gamma (rho / rho0 - 1) = c0^2 (rho - rho0): for a 0.1 %
  // compression the relative second-order term is (gamma - 1) / 2 * 1e-3 = 3e-3 (the third-order
  // one 5e-6).
  const double lin = 20.0 * 20.0 * 1.0;
  EXPECT_NEAR(e.pressure(1001.0), lin, 3.5e-3 * lin);
  // Exact value from the formula: kappa (1.001^7 - 1).
  EXPECT_NEAR(e.pressure(1001.0), e.kappa * (std::pow(1.001, 7.0) - 1.0),
              8.0 * kEps * e.kappa);  // a few ulp of kappa * 1.007 (cancellation in "- 1")
}

TEST(TaitEos, WholeExponentPowerMatchesPow) {
  // A whole gamma goes by repeated squaring (pressure's fast path), any other through pow: both
  // are a^gamma. For gamma = 7 (a^7 = a^4 a^2 a, three roundings compounded by squaring, at most
  // ~6 ulp) against the correctly rounded pow (< 1 ulp): 8 ulp of a^gamma.
  for (const double gamma : {1.0, 2.0, 7.0, 1.4}) {
    const TaitEos e = water(gamma);
    for (const double a : {0.5, 0.93, 0.999, 1.0, 1.0007, 1.02, 1.3}) {
      const double want = std::pow(a, gamma);
      EXPECT_NEAR(e.power(a), want, 8.0 * kEps * want) << "gamma " << gamma << " a " << a;
    }
    EXPECT_EQ(e.power(1.0), 1.0);  // products of ones, or pow(1, gamma): exactly 1
  }
  // gamma = 1 multiplies by a once: exact.
  EXPECT_EQ(water(1.0).power(1.2345), 1.2345);
}

// The block pass (the density sweep's equation of state) gives each particle exactly the
// values of pressure(rho) and sound_speed(rho, p): the same operations, vectorised or not.
TEST(TaitEos, BlockPassGivesThePerParticleValues) {
  const std::vector<double> rho{950.0, 999.0, 1000.0, 1000.5, 1013.0, 1070.0, 1100.0};
  for (const double gamma : {7.0, 1.4}) {  // the whole-exponent loop, and the pow path
    const TaitEos e = water(gamma);
    std::vector<double> p(rho.size(), -1.0), c(rho.size(), -1.0);
    e.pressure_and_sound_speed(rho.data(), p.data(), c.data(), 1, rho.size());
    EXPECT_EQ(p[0], -1.0);  // before the block: untouched
    EXPECT_EQ(c[0], -1.0);
    for (std::size_t i = 1; i < rho.size(); ++i) {
      EXPECT_EQ(p[i], e.pressure(rho[i])) << "gamma " << gamma << " rho " << rho[i];
      EXPECT_EQ(c[i], e.sound_speed(rho[i], e.pressure(rho[i]))) << "gamma " << gamma;
    }
  }
}

TEST(TaitEos, ReferenceSoundSpeed) {
  const TaitEos e = water();
  // sqrt(gamma kappa / rho0) = c0 = 20: a few ulp (pow(1, 6) = 1 exactly, one sqrt and the
  // round trip through kappa).
  EXPECT_NEAR(e.sound_speed(e.rho0), std::sqrt(e.gamma * e.kappa / e.rho0), 4.0 * kEps * 20.0);
  EXPECT_NEAR(e.sound_speed(e.rho0), 20.0, 8.0 * kEps * 20.0);
  EXPECT_EQ(e.reference_sound_speed(), std::sqrt(e.gamma * e.kappa / e.rho0));
}

// Central difference of f at x with step dx: error dx^2 / 6 |f'''| (truncation) plus
// ~ eps |f| / dx (round-off).
template <class F>
double central_difference(F f, double x, double dx) {
  return (f(x + dx) - f(x - dx)) / (2.0 * dx);
}

TEST(TaitEos, PressureDerivativeIsSoundSpeedSquared) {
  const TaitEos e = water();
  for (const double rho : {980.0, 1000.0, 1003.0, 1030.0}) {
    const double dx = 1e-3;  // kg/m^3
    const double fd = central_difference([&](double r) { return e.pressure(r); }, rho, dx);
    const double c = e.sound_speed(rho);
    // Truncation: p''' = kappa gamma (gamma-1)(gamma-2) rho^(gamma-3) / rho0^gamma ~ 210 kappa /
    // rho0^3 ~ 1.2e-2 near rho0 (3e-2 at 1030), times dx^2 / 6: ~5e-9. Round-off: p(rho +- dx)
    // carry ~ (gamma + 1) ulp of kappa (rho / rho0)^gamma ~ 8 * 2.2e-16 * 7.4e4 ~ 1.3e-10 each,
    // over 2 dx: ~1.3e-7. Against c^2 ~ 400 both are < 1e-9 relative; 1e-8 leaves a margin.
    EXPECT_NEAR(fd, c * c, 1e-8 * c * c) << "rho " << rho;
    // The pressure form: the same value up to the rounding of p, sqrt and pow (a few ulp of c).
    EXPECT_NEAR(e.sound_speed(rho, e.pressure(rho)), c, 8.0 * kEps * c) << "rho " << rho;
  }
}

TEST(TaitEos, InternalEnergyVanishesAtReferenceDensity) {
  for (const double gamma : {1.4, 7.0}) {
    const TaitEos e = water(gamma);
    // Both brackets are x - x with identical operands: exactly 0.
    EXPECT_EQ(e.specific_internal_energy(e.rho0), 0.0) << "gamma " << gamma;
  }
}

TEST(TaitEos, InternalEnergyDerivativeIsPOverRhoSquared) {
  for (const double gamma : {1.4, 7.0}) {
    const TaitEos e = water(gamma);
    for (const double rho : {970.0, 995.0, 1005.0, 1040.0}) {
      const double dx = 1e-2;
      const double fd =
          central_difference([&](double r) { return e.specific_internal_energy(r); }, rho, dx);
      const double want = e.pressure(rho) / (rho * rho);
      // Truncation dx^2 / 6 |e'''| with e' = p / rho^2, |e'''| ~ |p''| / rho^2 ~ c^2 gamma / rho^3
      // ~ 3e-6: ~5e-11. Round-off: e is a difference of terms up to kappa / (rho0 (gamma - 1))
      // ~ 700 (gamma = 1.4) that cancel, so f(x +- dx) carry a few ulp of 700 ~ 5e-13 each, over
      // 2 dx: ~5e-11. At rho = 995 the target is ~ -2e-3, so an absolute 1e-9 is still a
      // relative 5e-7 at worst.
      EXPECT_NEAR(fd, want, 1e-9) << "gamma " << gamma << " rho " << rho;
    }
  }
}

TEST(TaitEos, InternalEnergyIsPositiveAwayFromReference) {
  // e(rho) = int p / rho^2: p changes sign with rho - rho0, so e has a minimum 0 at rho0.
  const TaitEos e = water();
  EXPECT_GT(e.specific_internal_energy(1010.0), 0.0);
  EXPECT_GT(e.specific_internal_energy(990.0), 0.0);
}

// The column integrated independently: dp/dd = g rho(p), rho(p) = rho0 (1 + p/kappa)^(1/gamma),
// by classical RK4 from p = 0 in 20000 steps (error ~ (step)^4 relative: far below 1e-10),
// for gamma = 7 and gamma = 1 (the exponential branch).
TEST(TaitEos, HydrostaticDensityIsTheIntegratedColumn) {
  for (const double gamma : {7.0, 1.0}) {
    TaitEos e = water();
    e.gamma = gamma;
    const double g = 9.81;
    for (const double depth : {0.01, 0.2, 3.0, 40.0}) {
      const auto rho_of_p = [&](double p) {
        return e.rho0 * std::pow(1.0 + p / e.kappa, 1.0 / gamma);
      };
      double p = 0.0;
      const int n = 20000;
      const double h = depth / n;
      for (int k = 0; k < n; ++k) {
        const double k1 = g * rho_of_p(p), k2 = g * rho_of_p(p + 0.5 * h * k1);
        const double k3 = g * rho_of_p(p + 0.5 * h * k2), k4 = g * rho_of_p(p + h * k3);
        p += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      }
      EXPECT_NEAR(e.hydrostatic_density(g * depth), rho_of_p(p), 1e-10 * e.rho0)
          << "gamma " << gamma << " depth " << depth;
      // Heavier than rho0 g d: the column's own compression adds weight.
      EXPECT_GT(e.pressure(e.hydrostatic_density(g * depth)), e.rho0 * g * depth);
    }
    EXPECT_EQ(e.hydrostatic_density(0.0), e.rho0);  // pow(1, .) and exp(0) are exactly 1
  }
}

}  // namespace
}  // namespace flume
