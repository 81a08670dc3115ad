// The references validation computes from a run's own probes (validation/theory_reference.cpp):
// KdV's amplitude for the measured crest speed, the same statistic over an earlier window
// ("self"), the free fall of a drop; the "max" window statistic; variants with several
// overrides (validation/variant.hpp). Each against a hand computation on synthetic probes.
#include <gtest/gtest.h>

#include <cmath>

#include "flume/theory/solitary_wave.hpp"
#include "flume/validation/curve_compare.hpp"
#include "flume/validation/theory_reference.hpp"
#include "flume/validation/variant.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

std::string tank_toml(const std::string& curve) {
  return R"(
[case]
name = "tank"
end_time = 10.0
[particles]
spacing = 0.05
[domain]
min = [0.0, 0.0]
max = [10.0, 1.0]
[[fluid_blocks]]
min = [0.0, 0.0]
max = [10.0, 0.15]
[[fluid_blocks]]
min = [4.0, 0.6]
max = [4.2, 0.8]
shape = "ellipsoid"
hydrostatic = false
[probes]
waves = true
centre_of_mass = true
)" + curve;
}

// Probes of a crest moving at v with amplitude a, and a centre of mass y0 - c t^2.
io::CsvData synthetic(double v, double a, double y0, double c) {
  io::CsvData d;
  d.columns = {"time", "crest_x", "crest_amplitude", "centre_y"};
  for (int k = 0; k <= 100; ++k) {
    const double t = k / 10.0;
    d.rows.push_back({t, 0.3 + v * t, a + (k % 2 ? 1e-3 : -1e-3), y0 - c * t * t});
  }
  return d;
}

TEST(WaveReferences, KdvGivesTheAmplitudeOfTheMeasuredSpeed) {
  // Crest at 1.3 m/s on H = 0.15 m: KdV W (6.16) gives A = 2 H (1.3 / sqrt(g H) - 1).
  const auto spec = test::spec_from(tank_toml(R"(
[[validation.curves]]
probe = "crest_amplitude"
reference = "theory:kdv"
reference_x = "t"
reference_y = "amplitude"
statistic = "mean"
window_from = 3.0
window_to = 7.0
)"));
  const auto probes = synthetic(1.3, 0.02, 0.3, 0.0);
  const auto ref = curve_reference(spec, spec.curves.front(), probes);
  const double a_kdv = 2.0 * 0.15 * (1.3 / std::sqrt(9.81 * 0.15) - 1.0);
  ASSERT_EQ(ref.rows.size(), 41u);  // the output times t = 3.0 ... 7.0
  for (double a : ref.column("amplitude"))
    EXPECT_NEAR(a, a_kdv, 1e-12);
  // The crest track at KdV's speed of the measured amplitude (the mean of +-1e-3 about 0.02
  // over 41 points: 0.02 - 1e-3 / 41).
  const auto x = ref.column("crest_x"), t = ref.column("t");
  const double a_mean = 0.02 - 1e-3 / 41.0;
  EXPECT_NEAR((x.back() - x.front()) / (t.back() - t.front()), kdv_speed(a_mean, 0.15, 9.81), 1e-9);
  // KdV's width W (6.17) of the mean measured amplitude, sqrt(4 H^3 / (3 A)), by hand.
  for (double w : ref.column("width"))
    EXPECT_NEAR(w, std::sqrt(4.0 * 0.15 * 0.15 * 0.15 / (3.0 * a_mean)), 1e-12);
  // compared as validate does: the measured mean amplitude against a_kdv
  const auto points =
      compare_over_window(probes.column("time"), probes.column("crest_amplitude"), t,
                          ref.column("amplitude"), 1.0, 1.0, false, CurveStatistic::mean, 3.0, 7.0);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].error, std::abs(a_mean - a_kdv) / a_kdv, 1e-9);
}

TEST(WaveReferences, SelfIsTheSameStatisticOverTheReferenceWindow) {
  const auto spec = test::spec_from(tank_toml(R"(
[[validation.curves]]
probe = "crest_x"
reference = "self"
reference_from = 1.0
reference_to = 3.0
statistic = "slope"
window_from = 6.0
window_to = 9.0
)"));
  // A crest that slows from 1.3 to 1.2 m/s at t = 5 s.
  io::CsvData probes;
  probes.columns = {"time", "crest_x"};
  for (int k = 0; k <= 100; ++k) {
    const double t = k / 10.0;
    probes.rows.push_back({t, t < 5.0 ? 1.3 * t : 6.5 + 1.2 * (t - 5.0)});
  }
  const auto ref = curve_reference(spec, spec.curves.front(), probes);
  const auto points =
      compare_over_window(probes.column("time"), probes.column("crest_x"), ref.column("t"),
                          ref.column("value"), 1.0, 1.0, false, CurveStatistic::slope, 6.0, 9.0);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].value, 1.2, 1e-12);
  EXPECT_NEAR(points[0].reference, 1.3, 1e-12);
  EXPECT_NEAR(points[0].error, 0.1 / 1.3, 1e-12);
}

TEST(WaveReferences, SelfLineAtGivesThePhaseShift) {
  // A crest at 1.3 m/s that two waves' meeting at t = 3 s sets 0.12 m back (a KdV phase
  // shift), its speed unchanged: its track after (t = 4-6 s), extrapolated to t = 3 s, stands
  // 0.12 m behind its track before (t = 1-2.5 s). The error is the shift, in m.
  const auto spec = test::spec_from(tank_toml(R"(
[[validation.curves]]
probe = "crest_x"
reference = "self"
reference_from = 1.0
reference_to = 2.5
statistic = "line_at"
at = 3.0
window_from = 4.0
window_to = 6.0
error = "absolute"
)"));
  io::CsvData probes;
  probes.columns = {"time", "crest_x"};
  for (int k = 0; k <= 80; ++k) {
    const double t = k / 10.0;
    probes.rows.push_back({t, 0.2 + 1.3 * t - (t > 3.0 ? 0.12 : 0.0)});
  }
  const auto& check = spec.curves.front();
  ASSERT_EQ(check.statistic, CurveStatistic::line_at);
  const auto ref = curve_reference(spec, check, probes);
  const auto points = compare_over_window(probes.column("time"), probes.column("crest_x"),
                                          ref.column("t"), ref.column("value"), 1.0, 1.0, true,
                                          CurveStatistic::line_at, 4.0, 6.0, check.at);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].reference, 0.2 + 1.3 * 3.0, 1e-12);
  EXPECT_NEAR(points[0].value, 0.2 + 1.3 * 3.0 - 0.12, 1e-12);
  EXPECT_NEAR(points[0].error, 0.12, 1e-12);
}

TEST(WaveReferences, FreeFallOfTheLastBlock) {
  // The last block (a disc of radius 0.1 m, at rho0) falls while the layer (10 x 0.15 m)
  // rests: the centre of mass falls by f g t^2 / 2, f the disc's share of the particles'
  // mass. On this lattice (spacing 0.05 m) the disc holds 12 particles of rho0 dx^2 and the
  // layer 200 x 3 of its hydrostatic densities: f is within 2 % of the continuum's
  // pi 0.01 / (1.5 + pi 0.01) (its lattice holds 12 dx^2 = 0.03 for pi 0.01 = 0.0314).
  const auto spec = test::spec_from(tank_toml(R"(
[[validation.curves]]
probe = "centre_y"
reference = "theory:free_fall"
reference_x = "t"
reference_y = "centre_y"
)"));
  const auto probes = synthetic(1.3, 0.02, 0.3, 0.0);
  const auto ref = curve_reference(spec, spec.curves.front(), probes);
  const auto t = ref.column("t"), y = ref.column("centre_y");
  ASSERT_EQ(t.size(), 101u);
  const double f = (0.3 - y.back()) / (0.5 * 9.81 * t.back() * t.back());
  for (std::size_t k = 0; k < t.size(); ++k)
    EXPECT_NEAR(y[k], 0.3 - 0.5 * f * 9.81 * t[k] * t[k], 1e-12);  // a parabola in t
  // f from the lattice by hand: 12 disc particles of rho0 dx^2 against the layer's 600 of
  // rho dx^2, rho its Tait hydrostatic density: with c0 = 10 sqrt(2 g 0.2) = 19.8 m/s (BL (64),
  // the tallest block) the layer is denser than rho0 by g H / (2 c0^2) = 1.9e-3 on average, so
  // f is within 3e-3 of the rho0 figure; a mass fraction of the wrong block would be 50x off.
  const double disc = 12 * 1000.0 * 0.05 * 0.05, layer = 600 * 1000.0 * 0.05 * 0.05;
  EXPECT_NEAR(f, disc / (disc + layer), 3e-3 * disc / (disc + layer));
}

TEST(WaveReferences, MaxStatisticIsTheLargestValue) {
  const std::vector<double> t{0.0, 1.0, 2.0, 3.0}, y{0.1, 0.4, 0.2, 0.3};
  EXPECT_DOUBLE_EQ(window_statistic(t, y, CurveStatistic::max, 0.0, 3.0), 0.4);
  EXPECT_DOUBLE_EQ(window_statistic(t, y, CurveStatistic::max, 2.0, 3.0), 0.3);
  const auto p = compare_over_window(t, y, t, {0.0, 0.0, 0.0, 0.0}, 1.0, 1.0, true,
                                     CurveStatistic::max, 0.0, 3.0);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_DOUBLE_EQ(p[0].error, 0.4);
}

TEST(Variant, OneOverrideOrSeveralWithALabel) {
  const auto one = parse_variant("scheme.preset=csph");
  EXPECT_EQ(one.label, "csph");
  ASSERT_EQ(one.overrides.size(), 1u);
  const auto les = parse_variant("les-sph: scheme.preset=les-sph; scheme.alpha=0.0;scheme.beta=0");
  EXPECT_EQ(les.label, "les-sph");
  EXPECT_EQ(les.overrides, (std::vector<std::string>{"scheme.preset=les-sph", "scheme.alpha=0.0",
                                                     "scheme.beta=0"}));
  // A ':' inside a value (after the first '=') is not a label.
  const auto colon = parse_variant("validation.notes=[\"a: b\"]");
  EXPECT_EQ(colon.overrides.size(), 1u);
  EXPECT_EQ(colon.label, "[\"a: b\"]");
  EXPECT_NE(test::error_of(tank_toml("[validation]\nvariants = [\"x: scheme.alpha\"]\n")),
            "(no error)");
}

TEST(WaveReferences, PlotsTakeDiagnosticsOrProbeColumns) {
  // validation.diagnostics_plots names a column of diagnostics.csv or of the case's probes.csv
  // (a gauge's time series); anything else is refused with one line naming the key.
  const auto ok =
      test::spec_from(tank_toml("[validation]\ndiagnostics_plots = [\"rho_max\", \"crest_x\"]\n"));
  EXPECT_EQ(ok.diagnostics_plots.size(), 2u);
  test::expect_one_line_with(
      test::error_of(tank_toml("[validation]\ndiagnostics_plots = [\"gauge_1\"]\n")),
      {"validation.diagnostics_plots", "gauge_1"});
}

TEST(WaveReferences, CrestCurvesNeedTheProbesThatMeasureThem) {
  // crest_width and crest_shape are measured with probes.crest_profile only, crest2_* with
  // probes.second_crest only: a curve of either without it is one line naming the curve; and
  // crest_profile needs the wave probe.
  const std::string width = R"(
[[validation.curves]]
probe = "crest_width"
reference = "theory:kdv"
reference_x = "t"
reference_y = "width"
statistic = "mean"
)";
  test::expect_one_line_with(test::error_of(tank_toml(width)),
                             {"validation.curves[0].probe", "crest_width", "do not measure it"});
  EXPECT_TRUE(test::spec_from(tank_toml("crest_profile = true\n" + width)).crest_profile);
  std::string second = width;
  second.replace(second.find("crest_width"), 11, "crest2_amplitude");
  test::expect_one_line_with(test::error_of(tank_toml(second)),
                             {"crest2_amplitude", "do not measure it"});
  // crest2_fit_amplitude needs both.
  std::string fit2 = width;
  fit2.replace(fit2.find("crest_width"), 11, "crest2_fit_amplitude");
  test::expect_one_line_with(test::error_of(tank_toml("crest_profile = true\n" + fit2)),
                             {"crest2_fit_amplitude", "do not measure it"});
  std::string no_waves = tank_toml("crest_profile = true\n");
  no_waves.replace(no_waves.find("waves = true"), 12, "waves = false");
  test::expect_one_line_with(test::error_of(no_waves),
                             {"probes.crest_profile", "needs probes.waves"});
}

}  // namespace
}  // namespace flume
