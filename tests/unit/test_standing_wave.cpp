// The sloshing tank's reference and statistic (theory/standing_wave.hpp; validation's
// "period" statistic and theory:standing_wave, cases/sloshing_tank.toml): the first mode's
// period against its deep- and shallow-water limits and a hand computation, the mean period
// of sampled oscillations, and the reference's depth from the water as laid out.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flume/core/error.hpp"
#include "flume/theory/standing_wave.hpp"
#include "flume/validation/curve_compare.hpp"
#include "flume/validation/theory_reference.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(StandingWave, PeriodHasTheDeepAndShallowWaterLimits) {
  const double g = 9.81, L = 2.0;
  // Deep water (k H = 31): tanh = 1 to 1e-27, T = 2 pi / sqrt(g k), k = pi / L.
  EXPECT_NEAR(standing_wave_period(1, L, 20.0, g), 2.0 * kPi / std::sqrt(g * kPi / L), 1e-12);
  // Shallow water: the wave travels 2 L (there and back) at sqrt(g H), up to the dispersion
  // tanh(kH) = kH (1 - (kH)^2 / 3 + ...): T = 2 L / sqrt(g H) (1 + (k H)^2 / 6) to
  // O((kH)^4), here kH = pi / 2000 so the bracket differs from 1 by 4e-7.
  const double H = 1e-3, kH = kPi / L * H;
  EXPECT_NEAR(standing_wave_period(1, L, H, g), 2.0 * L / std::sqrt(g * H) * (1.0 + kH * kH / 6.0),
              1e-9 * 2.0 * L / std::sqrt(g * H));
  // Mode 2 is mode 1 of a tank half as long.
  EXPECT_DOUBLE_EQ(standing_wave_period(2, L, 0.3, g), standing_wave_period(1, L / 2.0, 0.3, g));
  // The bundled tank's numbers, by hand (Python's math): L = 1 m, H = 0.186 m.
  EXPECT_NEAR(standing_wave_period(1, 1.0, 0.186, 9.81), 1.5608315280686789, 1e-12);
}

TEST(StandingWave, MeanPeriodOfASampledOscillation) {
  // A sine of period 1.5637 s about an offset, sampled every 0.01 s over 8 s: the upward
  // crossings of its mean are placed by linear interpolation, exact to O(dt^3 omega^2) at a
  // crossing, where the sine is straight to second order: 1e-6 s here. The window's mean is
  // not the sine's centre (8 s is not a whole number of periods), which moves every upward
  // crossing by the same time and leaves the period as it is.
  const double T = 1.5637;  // not a whole number of samples: the crossings fall between them
  std::vector<double> t, y;
  for (int k = 0; k <= 800; ++k) {
    t.push_back(0.01 * k);
    y.push_back(0.5 + 0.01 * std::sin(2.0 * kPi * t.back() / T + 0.3));
  }
  EXPECT_NEAR(mean_period(t, y), T, 1e-5);
  EXPECT_NEAR(window_statistic(t, y, CurveStatistic::period, 0.3, 8.0), T, 1e-5);
  // Fewer than two upward crossings: no period.
  EXPECT_TRUE(std::isnan(window_statistic(t, y, CurveStatistic::period, 0.0, 1.5)));
  // Compared as validate does: against a constant reference, the error is relative.
  const std::vector<double> rt{1.0, 4.0, 8.0}, ry{1.5, 1.5, 1.5};
  const auto p =
      compare_over_window(t, y, rt, ry, 1.0, 1.0, false, CurveStatistic::period, 0.3, 8.0);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(p[0].value, T, 1e-5);
  EXPECT_NEAR(p[0].error, (T - 1.5) / 1.5, 1e-5);
  // A run that stopped before the window's end is not summarised.
  t.resize(400);
  y.resize(400);
  EXPECT_TRUE(
      compare_over_window(t, y, rt, ry, 1.0, 1.0, false, CurveStatistic::period, 0.3, 8.0).empty());
}

std::string slosh_toml(const std::string& statistic) {
  return R"(
[case]
name = "slosh"
end_time = 2.0
[particles]
spacing = 0.02
[domain]
min = [0.0, 0.0]
max = [1.0, 0.5]
[[fluid_blocks]]
min = [0.0, 0.0]
max = [1.0, 0.16]
[probes]
centre_of_mass = true
[[validation.curves]]
probe = "centre_x"
reference = "theory:standing_wave"
reference_x = "t"
reference_y = "period"
statistic = ")" +
         statistic +
         R"("
window_from = 0.3
)";
}

TEST(StandingWave, ReferenceTakesTheDepthOfTheWaterAsLaidOut) {
  // 50 x 8 particles of 0.02 m: the water's volume is 0.16 m^2 over L = 1 m, H = 0.16 m (a
  // hydrostatic start makes them denser than rho0 but leaves their volumes dx^2).
  const auto spec = test::spec_from(slosh_toml("period"));
  io::CsvData probes;
  probes.columns = {"time", "centre_x"};
  for (int k = 0; k <= 20; ++k)
    probes.rows.push_back({0.1 * k, 0.5});
  const auto ref = curve_reference(spec, spec.curves.front(), probes);
  const auto t = ref.column("t"), period = ref.column("period");
  ASSERT_EQ(t.size(), 18u);  // the output times t = 0.3 ... 2.0
  const double k = kPi, expected = 2.0 * kPi / std::sqrt(9.81 * k * std::tanh(k * 0.16));
  for (double p : period)
    EXPECT_NEAR(p, expected, 1e-9 * expected);
  // Not a closed tank (periodic ends): refused, in one line naming the file and the reference.
  auto periodic = spec;
  periodic.walls[0] = periodic.walls[1] = "periodic";
  EXPECT_THROW(curve_reference(periodic, spec.curves.front(), probes), InputError);
  // The reference gives a period: it takes the period statistic and no other.
  EXPECT_NE(test::error_of(slosh_toml("mean")).find("must be \"period\""), std::string::npos)
      << test::error_of(slosh_toml("mean"));
}

}  // namespace
}  // namespace flume
