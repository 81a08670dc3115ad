// The case keys of the thesis's options (viscous term, LES-SPH, XSPH, the W (3.88) step): each
// resolves from a case file, and each bad value is refused with one line naming the file, the
// key and what is allowed.
#include <gtest/gtest.h>

#include "flume/case/build_simulation.hpp"
#include "flume/core/error.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

const std::string kValid = test::dam_break_toml("continuity", 10, 0.01);

using test::expect_one_line_with;

TEST(CaseReaderThesisOptions, DefaultsAndThePresetOfLesSph) {
  auto spec = test::spec_from(kValid);
  EXPECT_EQ(spec.viscous_term, "bl24");
  EXPECT_EQ(spec.turbulence, "none");
  EXPECT_EQ(spec.time_step, "bl63");
  EXPECT_EQ(spec.xsph, 0.0);
  spec = test::spec_from(kValid, {"scheme.preset=les-sph"});
  EXPECT_EQ(spec.density + "+" + spec.force + "+" + spec.correction, "w379+w380+none");
  EXPECT_EQ(spec.turbulence, "smagorinsky");
  // The resolved file names the row, so the run repeats as LES-SPH.
  EXPECT_NE(spec.resolved_toml.find("turbulence = 'smagorinsky'"), std::string::npos);
  // Physics from the case: Delta defaults to the spacing (W), C_s and C_I to W's constants.
  const auto phys = build_physics<2>(spec);
  EXPECT_TRUE(phys.les.on);
  EXPECT_EQ(phys.les.delta, spec.spacing);
  EXPECT_EQ(phys.les.cs, 0.12);
  EXPECT_EQ(phys.les.ci, 0.0066);
  spec = test::spec_from(kValid, {"scheme.viscous_term=w57", "fluid.viscosity=0.01",
                                  "scheme.turbulence=smagorinsky", "scheme.filter_width=0.003"});
  const auto phys2 = build_physics<2>(spec);
  EXPECT_EQ(phys2.viscous, ViscousTerm::w57);
  EXPECT_TRUE(phys2.morris_term());
  EXPECT_TRUE(phys2.stress_term());  // the sub-grid stress
  EXPECT_EQ(phys2.les.delta, 0.003);
}

TEST(CaseReaderThesisOptions, BadValuesAreRefused) {
  expect_one_line_with(test::error_of(kValid, {"scheme.viscous_term=laplacian"}),
                       {"scheme.viscous_term", "bl24, w511, w57"});
  expect_one_line_with(test::error_of(kValid, {"scheme.turbulence=k_epsilon"}),
                       {"scheme.turbulence", "none, smagorinsky"});
  expect_one_line_with(test::error_of(kValid, {"scheme.time_step=courant"}),
                       {"scheme.time_step", "bl63, w388"});
  expect_one_line_with(test::error_of(kValid, {"scheme.xsph=1.5"}), {"scheme.xsph", "[0, 1]"});
  expect_one_line_with(test::error_of(kValid, {"scheme.smagorinsky_cs=-0.1"}),
                       {"scheme.smagorinsky_cs", "[0, 1]"});
  expect_one_line_with(test::error_of(kValid, {"scheme.filter_width=-1"}), {"scheme.filter_width"});
  // The corrected forces carry BL (22)-(25)'s stress themselves.
  expect_one_line_with(test::error_of(kValid, {"scheme.preset=csph", "scheme.viscous_term=w511"}),
                       {"scheme.viscous_term", "correction \"mixed\"", "bl24"});
  expect_one_line_with(
      test::error_of(kValid, {"scheme.preset=csph", "scheme.turbulence=smagorinsky"}),
      {"scheme.turbulence", "correction \"mixed\""});
}

}  // namespace
}  // namespace flume
