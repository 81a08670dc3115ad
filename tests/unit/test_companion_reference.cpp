// reference = "run:LABEL" (validation/theory_reference.cpp): a curve compared with the same
// statistic of a companion run's probe over the same window (a wave's height and place after
// a collision against the same wave's alone in the same tank), and the case file's rules for
// validation.companions. Each against a hand computation on synthetic probes.
#include <gtest/gtest.h>

#include <cmath>

#include "flume/validation/curve_compare.hpp"
#include "flume/validation/theory_reference.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

std::string tank_toml(const std::string& validation) {
  return R"(
[case]
name = "tank"
end_time = 8.0
[particles]
spacing = 0.05
[domain]
min = [0.0, 0.0]
max = [10.0, 1.0]
[[fluid_blocks]]
min = [0.0, 0.0]
max = [5.0, 0.15]
surface_amplitude = 0.07
surface_decay = 2.5
[[fluid_blocks]]
min = [5.0, 0.0]
max = [10.0, 0.15]
surface_amplitude = 0.05
surface_decay = 2.5
surface_from = "x_max"
[probes]
waves = true
second_crest = 1.0
)" + validation;
}

const std::string kCompanions = R"(
[validation]
companions = ["large-alone: fluid_blocks.1.surface_amplitude=0.0",
              "small-alone: fluid_blocks.0.surface_amplitude=0.0"]
)";

// Probes every 0.1 s to t = 8 s: column `name` = f(t).
template <class F>
io::CsvData series(const std::string& name, F f) {
  io::CsvData d;
  d.columns = {"time", name};
  for (int k = 0; k <= 80; ++k) {
    const double t = k / 10.0;
    d.rows.push_back({t, f(t)});
  }
  return d;
}

TEST(CompanionReference, HeightAgainstTheSameWaveAloneAtTheSameTimes) {
  // The small wave (crest2) after the meeting, t = 4-6 s: alone it decays as 0.012 - 0.0005 t;
  // with the other wave it stands 0.0003 m lower at every time. The mean over the window's 21
  // points: alone 0.012 - 0.0005 x 5 = 0.0095, met 0.0092; relative error 0.0003 / 0.0095.
  const auto spec = test::spec_from(tank_toml(kCompanions + R"(
[[validation.curves]]
probe = "crest2_amplitude"
reference = "run:small-alone"
reference_probe = "crest_amplitude"
statistic = "mean"
window_from = 4.0
window_to = 6.0
)"));
  const auto& check = spec.curves.front();
  EXPECT_EQ(check.theory, "run");
  EXPECT_EQ(check.companion, "small-alone");
  EXPECT_EQ(check.reference_probe, "crest_amplitude");
  const auto alone = series("crest_amplitude", [](double t) { return 0.012 - 0.0005 * t; });
  const auto met = series("crest2_amplitude", [](double t) { return 0.0117 - 0.0005 * t; });
  const auto ref = curve_reference(spec, check, met, &alone);
  ASSERT_EQ(ref.rows.size(), 81u);  // the companion's whole run, at its own times
  const auto points =
      compare_over_window(met.column("time"), met.column("crest2_amplitude"), ref.column("t"),
                          ref.column("value"), 1.0, 1.0, false, CurveStatistic::mean, 4.0, 6.0);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].reference, 0.0095, 1e-12);
  EXPECT_NEAR(points[0].value, 0.0092, 1e-12);
  EXPECT_NEAR(points[0].error, 0.0003 / 0.0095, 1e-9);
}

TEST(CompanionReference, PlaceAgainstTheWaveAloneIsThePhaseShift) {
  // The large wave runs at 1.3 m/s; the meeting sets it 0.12 m ahead (KdV shifts the larger
  // wave forward). The mean place over t = 4-6 s against the lone wave's: 0.12 m (the reference
  // probe defaults to the curve's own).
  const auto spec = test::spec_from(tank_toml(kCompanions + R"(
[[validation.curves]]
probe = "crest_x"
reference = "run:large-alone"
statistic = "mean"
error = "absolute"
window_from = 4.0
window_to = 6.0
)"));
  const auto& check = spec.curves.front();
  EXPECT_EQ(check.reference_probe, "crest_x");
  const auto alone = series("crest_x", [](double t) { return 0.5 + 1.3 * t; });
  const auto met = series("crest_x", [](double t) { return 0.5 + 1.3 * t + (t > 3 ? 0.12 : 0); });
  const auto ref = curve_reference(spec, check, met, &alone);
  const auto points =
      compare_over_window(met.column("time"), met.column("crest_x"), ref.column("t"),
                          ref.column("value"), 1.0, 1.0, true, CurveStatistic::mean, 4.0, 6.0);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].value - points[0].reference, 0.12, 1e-12);
  EXPECT_NEAR(points[0].error, 0.12, 1e-12);
}

TEST(CompanionReference, NoCompanionRunNoPoints) {
  // A companion that did not complete gives a table without rows: the check has no points
  // (reported as not compared), not a comparison with zeros.
  const auto spec = test::spec_from(tank_toml(kCompanions + R"(
[[validation.curves]]
probe = "crest_amplitude"
reference = "run:large-alone"
statistic = "mean"
window_from = 4.0
window_to = 6.0
)"));
  EXPECT_EQ(spec.curves.front().reference_probe, "crest_amplitude");  // the probe's own
  const auto met = series("crest_amplitude", [](double) { return 0.02; });
  const auto ref = curve_reference(spec, spec.curves.front(), met, nullptr);
  EXPECT_TRUE(ref.rows.empty());
  EXPECT_TRUE(compare_over_window(met.column("time"), met.column("crest_amplitude"),
                                  ref.column("t"), ref.column("value"), 1.0, 1.0, false,
                                  CurveStatistic::mean, 4.0, 6.0)
                  .empty());
}

TEST(CompanionReference, CaseFileRules) {
  const std::string curve = R"(
[[validation.curves]]
probe = "crest_amplitude"
statistic = "mean"
)";
  // A label that no companion has.
  test::expect_one_line_with(
      test::error_of(tank_toml(kCompanions + curve + "reference = \"run:nobody\"\n")),
      {"validation.curves[0].reference", "run:nobody", "companions"});
  // A reference probe the case does not measure.
  test::expect_one_line_with(
      test::error_of(tank_toml(kCompanions + curve +
                               "reference = \"run:large-alone\"\nreference_probe = \"bore_x\"\n")),
      {"validation.curves[0].reference_probe", "bore_x"});
  // A companion without a label, one that is not KEY=VALUE, a label given twice.
  test::expect_one_line_with(
      test::error_of(tank_toml("[validation]\ncompanions = [\"case.dt=1e-4\"]\n")),
      {"validation.companions", "LABEL"});
  test::expect_one_line_with(
      test::error_of(tank_toml("[validation]\ncompanions = [\"a: case.dt\"]\n")),
      {"validation.companions", "not KEY=VALUE"});
  test::expect_one_line_with(
      test::error_of(tank_toml("[validation]\ncompanions = [\"a: case.dt=1e-4\", \"a: "
                               "case.dt=2e-4\"]\n")),
      {"validation.companions", "\"a\"", "twice"});
}

TEST(CrestPictures, TimesWithinTheRunAndAWaveTank) {
  // Times after the end are left out (a shortened run draws what it has); a tank without the
  // wave probes has no crest to draw.
  const auto spec = test::spec_from(tank_toml("[validation]\ncrest_pictures = [2.0, 7.5, 9.0]\n"));
  EXPECT_EQ(spec.crest_pictures, (std::vector<double>{2.0, 7.5}));
  auto no_waves = tank_toml("[validation]\ncrest_pictures = [2.0]\n");
  no_waves.replace(no_waves.find("waves = true"), 12, "waves = false");
  no_waves.replace(no_waves.find("second_crest = 1.0"), 18, "");
  test::expect_one_line_with(test::error_of(no_waves),
                             {"validation.crest_pictures", "probes.waves"});
  test::expect_one_line_with(test::error_of(tank_toml("[validation]\ncrest_pictures = [-1.0]\n")),
                             {"validation.crest_pictures", ">= 0"});
}

}  // namespace
}  // namespace flume
