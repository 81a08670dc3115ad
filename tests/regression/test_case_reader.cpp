// The case-file reader: a valid file resolves with every default; bad input is rejected with
// flume::InputError and one line naming the file, the key and what is allowed.
#include <gtest/gtest.h>

#include "flume/core/error.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

const std::string kValid = test::dam_break_toml("continuity", 10, 0.01);

using test::error_of;

using test::expect_one_line_with;

TEST(CaseReader, ValidFileResolvesEveryDefault) {
  const auto spec = test::spec_from(kValid);
  EXPECT_EQ(spec.name, "small_dam_break");
  EXPECT_EQ(spec.density, "continuity");
  EXPECT_EQ(spec.force, "bl20");
  EXPECT_EQ(spec.kernel, "cubic_spline");
  // c0 = 10 sqrt(2 g a) (BL (66)), kappa = rho0 c0^2 / gamma.
  const double c0 = 10.0 * std::sqrt(2.0 * 9.81 * 0.05715);
  EXPECT_NEAR(spec.sound_speed, c0, 1e-12 * c0);
  EXPECT_NEAR(spec.bulk_modulus, 1000.0 * c0 * c0 / 7.0, 1e-9 * spec.bulk_modulus);
  for (const char* key : {"h_over_dx", "cfl", "speed_ratio", "floor_layer", "snapshot_interval",
                          "x_max", "bulk_modulus", "density = 'continuity'"})
    EXPECT_NE(spec.resolved_toml.find(key), std::string::npos) << key;
}

TEST(CaseReader, ResolvedFileReadsBackToTheSameSpec) {
  const auto spec = test::spec_from(kValid);
  const auto again = test::spec_from(spec.resolved_toml);
  EXPECT_EQ(again.resolved_toml, spec.resolved_toml);
  EXPECT_EQ(again.bulk_modulus, spec.bulk_modulus);
}

TEST(CaseReader, PresetRowsAndOverrides) {
  auto spec = test::spec_from(kValid, {"scheme.preset=standard", "particles.spacing=0.002",
                                       "case.end_time=0.5", "fluid_blocks[0].velocity=[1.0, 0.0]"});
  EXPECT_EQ(spec.density, "summation");
  EXPECT_EQ(spec.force, "bl7");
  EXPECT_EQ(spec.spacing, 0.002);
  EXPECT_EQ(spec.end_time, 0.5);
  EXPECT_EQ(spec.blocks[0].velocity[0], 1.0);
  spec = test::spec_from(kValid, {"scheme.preset=inconsistent"});
  EXPECT_EQ(spec.density + "+" + spec.force, "summation+bl20");
}

TEST(CaseReader, UnknownKeyIsAnError) {
  expect_one_line_with(error_of(kValid + "\n[output.extra]\nfoo = 1\n"),
                       {"output.extra", "unknown key"});
  std::string bad = kValid;
  bad.replace(bad.find("[scheme]"), 8, "[scheme]\nflavour = \"x\"");
  expect_one_line_with(error_of(bad), {"scheme.flavour", "unknown key", "preset"});
  expect_one_line_with(error_of(kValid + "\n[solver]\nx = 1\n"), {"solver", "unknown key"});
}

TEST(CaseReader, WrongTypeIsAnError) {
  std::string bad = kValid;
  bad.replace(bad.find("preset = "), 9, "preset = 3 #");
  expect_one_line_with(error_of(bad), {"scheme.preset", "must be a string"});
  expect_one_line_with(error_of(kValid, {"particles.spacing=\"fine\""}),
                       {"particles.spacing", "must be a number"});
  expect_one_line_with(error_of(kValid, {"fluid.gravity=[1.0]"}),
                       {"fluid.gravity", "array of 2 numbers"});
}

TEST(CaseReader, OutOfRangeValueIsAnError) {
  expect_one_line_with(error_of(kValid, {"particles.spacing=-0.001"}),
                       {"particles.spacing", "must be > 0"});
  expect_one_line_with(error_of(kValid, {"scheme.h_over_dx=9"}), {"scheme.h_over_dx", "[0.5, 4]"});
  expect_one_line_with(error_of(kValid, {"scheme.kernel=spline"}),
                       {"scheme.kernel", "cubic_spline", "wendland_c2"});
  expect_one_line_with(error_of(kValid, {"scheme.preset=csph9"}), {"scheme.preset", "standard"});
  expect_one_line_with(error_of(kValid, {"boundaries.y_min=sticky"}),
                       {"boundaries.y_min", "no_slip"});
  expect_one_line_with(error_of(kValid, {"case.dimension=4"}), {"case.dimension", "2 or 3"});
  expect_one_line_with(error_of(kValid, {"fluid_blocks[0].max=[0.5, 0.05]"}),
                       {"fluid_blocks[0]", "inside the domain"});
  expect_one_line_with(error_of(kValid, {"scheme.density=continuity", "scheme.force=bl7"}),
                       {"scheme.force", "continuity+bl20"});
  expect_one_line_with(error_of(kValid, {"scheme.shepard_every=-1"}),
                       {"scheme.shepard_every", ">= 0"});
  // A summation density is recomputed every step: a density filter would do nothing.
  expect_one_line_with(error_of(kValid, {"scheme.preset=standard", "scheme.shepard_every=40"}),
                       {"scheme.shepard_every", "summation", "must be 0"});
  EXPECT_EQ(test::spec_from(kValid, {"scheme.shepard_every=40"}).shepard_every, 40);
  EXPECT_EQ(test::spec_from(kValid, {}).density_filter, "shepard");  // W (6.3) unless asked
  EXPECT_EQ(test::spec_from(kValid, {"scheme.density_filter=first_order"}).density_filter,
            "first_order");
  expect_one_line_with(error_of(kValid, {"scheme.density_filter=mls"}),
                       {"scheme.density_filter", "shepard", "first_order"});
  EXPECT_EQ(test::spec_from(kValid, {}).ghost_pressure, "mirrored");  // W 6.1 unless asked
  EXPECT_EQ(test::spec_from(kValid, {"boundaries.ghost_pressure=hydrostatic"}).ghost_pressure,
            "hydrostatic");
  expect_one_line_with(error_of(kValid, {"boundaries.ghost_pressure=linear"}),
                       {"boundaries.ghost_pressure", "mirrored", "hydrostatic"});
  // The hydrostatic step is a Tait liquid's: a gas is refused.
  expect_one_line_with(error_of(kValid, {"scheme.preset=sph-euler", "eos.kind=ideal_gas",
                                         "boundaries.ghost_pressure=hydrostatic"}),
                       {"boundaries.ghost_pressure", "tait"});
}

TEST(CaseReader, BadOverridesAndSyntax) {
  expect_one_line_with(error_of(kValid, {"scheme.flux=3"}), {"scheme.flux", "unknown key"});
  expect_one_line_with(error_of(kValid, {"fluid_blocks[3].min=[0.0, 0.0]"}),
                       {"fluid_blocks", "unknown key"});
  EXPECT_NE(error_of(kValid, {"novalue"}).find("KEY=VALUE"), std::string::npos);
  expect_one_line_with(error_of("[case\nname = 1"), {"TOML syntax error"});
  expect_one_line_with(error_of("[case]\nname = \"x\"\n"), {"fluid_blocks", "at least one"});
  expect_one_line_with(error_of("[case]\nname = \"\"\n"), {"case.name", "required"});
}

// [[moving_walls]]: a wall side with a prescribed motion (the bore's push wall). The domain of
// kValid is 4 a = 0.2286 m long and the run 0.01 s.
TEST(CaseReader, MovingWalls) {
  const std::string piston = kValid + "\n[[moving_walls]]\nside = \"x_max\"\nvelocity = -1.0\n";
  const auto spec = test::spec_from(piston);
  ASSERT_EQ(spec.moving_walls.size(), 1u);
  EXPECT_EQ(spec.moving_walls[0].axis, 0);
  EXPECT_EQ(spec.moving_walls[0].side, 1);
  EXPECT_EQ(spec.moving_walls[0].velocity, -1.0);
  EXPECT_NE(spec.resolved_toml.find("moving_walls"), std::string::npos);
  EXPECT_EQ(test::spec_from(spec.resolved_toml).moving_walls.size(), 1u);
  expect_one_line_with(error_of(piston, {"moving_walls[0].side=w_max"}),
                       {"moving_walls[0].side", "x_min, x_max, y_min, y_max"});
  expect_one_line_with(error_of(piston, {"boundaries.x_max=open"}),
                       {"moving_walls[0].side", "open"});
  expect_one_line_with(error_of(piston, {"moving_walls[0].amplitude=0.01"}),
                       {"moving_walls[0].period", "> 0"});
  // 30 m/s for 0.01 s is 0.3 m: through the far wall.
  expect_one_line_with(error_of(piston, {"moving_walls[0].velocity=-30.0"}),
                       {"moving_walls[0].velocity", "opposite side"});
  expect_one_line_with(error_of(piston + "\n[[moving_walls]]\nside = \"x_max\"\n"),
                       {"moving_walls[1].side", "two entries"});
  expect_one_line_with(error_of(piston, {"moving_walls[0].speed=1.0"}),
                       {"moving_walls[0].speed", "unknown key"});
}

// [validation] pictures: times >= 0, numbers, those after the end left out;
// diagnostics_plots: strings.
TEST(CaseReader, PictureTimesAndDiagnosticsPlots) {
  const auto spec = test::spec_from(
      kValid,
      {"validation.pictures=[0.0, 0.005]", "validation.diagnostics_plots=[\"angular_momentum\"]"});
  EXPECT_EQ(spec.pictures, (std::vector<double>{0.0, 0.005}));
  EXPECT_EQ(spec.picture_field, "velocity_x");
  EXPECT_EQ(spec.diagnostics_plots, (std::vector<std::string>{"angular_momentum"}));
  expect_one_line_with(error_of(kValid, {"validation.pictures=[-0.5]"}),
                       {"validation.pictures", ">= 0"});
  // Times after the end are left out (a run shortened with --set keeps working).
  EXPECT_EQ(test::spec_from(kValid, {"validation.pictures=[0.0, 0.5]"}).pictures,
            (std::vector<double>{0.0}));
  expect_one_line_with(error_of(kValid, {"validation.pictures=[\"late\"]"}),
                       {"validation.pictures", "array of numbers"});
  expect_one_line_with(error_of(kValid, {"validation.variants=[1.0]"}),
                       {"validation.variants", "array of strings"});
  // The picture's field is one that snapshots hold: a misspelt one drew no picture before.
  expect_one_line_with(error_of(kValid, {"validation.picture_field=\"velocty\""}),
                       {"validation.picture_field", "velocity_x"});
  expect_one_line_with(error_of(kValid, {"validation.picture_field=\"internal_energy\""}),
                       {"validation.picture_field"});  // a liquid has none in its snapshots
  EXPECT_EQ(test::spec_from(kValid, {"validation.picture_field=\"pressure\""}).picture_field,
            "pressure");
}

TEST(CaseReader, ConvergenceStudy) {
  // A curve for the study to follow (the small dam break measures the surge front).
  const std::string curve = kValid +
                            "\n"
                            "[[validation.curves]]\nprobe = \"surge_front\"\n"
                            "reference = \"theory:bore\"\n";
  const auto spec = test::spec_from(curve, {"validation.convergence_spacings=[0.02, 0.01, 0.005]",
                                            "validation.convergence_sets=[\"scheme.cfl=0.1\"]"});
  EXPECT_EQ(spec.convergence_spacings, (std::vector<double>{0.02, 0.01, 0.005}));
  EXPECT_TRUE(spec.quick_convergence_spacings.empty());
  EXPECT_EQ(spec.convergence_sets, std::vector<std::string>{"scheme.cfl=0.1"});
  EXPECT_EQ(spec.convergence_curve, 0u);
  expect_one_line_with(error_of(curve, {"validation.convergence_spacings=[0.01]"}),
                       {"validation.convergence_spacings", "at least two"});
  expect_one_line_with(error_of(curve, {"validation.quick_convergence_spacings=[0.01, 0.02]"}),
                       {"validation.quick_convergence_spacings", "coarse to fine"});
  expect_one_line_with(error_of(curve, {"validation.convergence_spacings=[0.02, -0.01]"}),
                       {"validation.convergence_spacings", "> 0"});
  expect_one_line_with(error_of(curve, {"validation.convergence_sets=[\"cfl\"]"}),
                       {"validation.convergence_sets", "KEY=VALUE"});
  expect_one_line_with(error_of(curve, {"validation.convergence_spacings=[0.02, 0.01]",
                                        "validation.convergence_curve=1"}),
                       {"validation.convergence_curve", "1 [[validation.curves]]"});
  // A block with its own spacing would not be refined by particles.spacing.
  expect_one_line_with(error_of(curve, {"validation.convergence_spacings=[0.02, 0.01]",
                                        "fluid_blocks[0].spacing=0.01"}),
                       {"validation.convergence_spacings", "fluid_blocks[0]", "lattice"});
}

}  // namespace
}  // namespace flume
