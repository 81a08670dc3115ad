// Unit tests of a case's convergence study (validation.convergence_spacings): the spacing
// override, the order between two levels of any spacing ratio, and the results.json rows, each
// against values worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "flume/validation/convergence.hpp"
#include "flume/validation/convergence_rows.hpp"

namespace flume {
namespace {

TEST(ConvergenceStudy, SpacingOverrideIsATomlFloat) {
  EXPECT_EQ(spacing_override(0.02575), "particles.spacing=0.02575");
  EXPECT_EQ(spacing_override(1.0), "particles.spacing=1.0");  // "1" would be a TOML integer
}

TEST(ConvergenceStudy, OrderOverAnySpacingRatio) {
  // Errors 9e-4 -> 1e-4 while the spacing falls threefold: 9 = 3^2, second order.
  EXPECT_NEAR(observed_order(9e-4, 1e-4, 0.03, 0.01), 2.0, 1e-12);
  // Halving: 4e-4 -> 1e-4 is second order; 1e-4 -> 1e-4 is zeroth.
  EXPECT_NEAR(observed_order(4e-4, 1e-4, 0.02, 0.01), 2.0, 1e-12);
  EXPECT_EQ(observed_order(1e-4, 1e-4, 0.02, 0.01), 0.0);
  EXPECT_TRUE(std::isnan(observed_order(0.0, 1e-4, 0.02, 0.01)));
}

// A study of three levels whose followed curve's largest errors are e.
CaseResult study_of(const std::vector<double>& e) {
  CaseResult cr;
  cr.spec.name = "drop";
  cr.spec.curves.resize(1);
  cr.spec.curves[0].probe = "semi_axis_y";
  cr.spec.curves[0].source = "exact";
  double spacing = 0.04;
  for (double err : e) {
    StudyLevel level;
    level.spacing = spacing;
    level.run.completed = true;
    level.max_error = err;
    cr.study.push_back(level);
    spacing /= 2.0;
  }
  return cr;
}

TEST(ConvergenceStudy, OneRowPerStepWithTheRatio) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  EXPECT_TRUE(add_study_rows(study_of({1e-4, 2e-5, 1e-5}), rows));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["value"].get<double>(), 2e-5);
  EXPECT_EQ(rows[0]["reference"].get<double>(), 1e-4);
  EXPECT_EQ(rows[0]["error"].get<double>(), 2e-5 / 1e-4);
  EXPECT_EQ(rows[1]["error"].get<double>(), 0.5);
  EXPECT_NE(rows[1]["metric"].get<std::string>().find("from 0.02 m to 0.01 m"), std::string::npos);
  for (const auto& r : rows) {
    EXPECT_TRUE(r["pass"].get<bool>());
    EXPECT_TRUE(r["gated"].get<bool>());
  }
}

TEST(ConvergenceStudy, AnErrorThatStopsFallingFailsValidation) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  // The last step keeps 2e-5: ratio 1, not below it.
  EXPECT_FALSE(add_study_rows(study_of({1e-4, 2e-5, 2e-5}), rows));
  EXPECT_TRUE(rows[0]["pass"].get<bool>());
  EXPECT_FALSE(rows[1]["pass"].get<bool>());
}

TEST(ConvergenceStudy, AFailedLevelFailsItsStepsAndSaysWhy) {
  auto cr = study_of({1e-4, 2e-5, 1e-5});
  cr.study[2].run.completed = false;
  cr.study[2].run.error = "density below the band";
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  EXPECT_FALSE(add_study_rows(cr, rows));
  EXPECT_TRUE(rows[0]["pass"].get<bool>());
  EXPECT_TRUE(rows[1]["value"].is_null());
  EXPECT_EQ(rows[1]["error"].get<std::string>(), "density below the band");
  // A run that completed without a point of the curve (it ended before the curve's window).
  cr = study_of({1e-4, std::nan(""), 1e-5});
  rows = nlohmann::ordered_json::array();
  EXPECT_FALSE(add_study_rows(cr, rows));
  EXPECT_EQ(rows[0]["error"].get<std::string>(), "no point of the curve compared");
  EXPECT_FALSE(rows[1]["pass"].get<bool>());
}

TEST(ConvergenceStudy, NoStudyNoRows) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  EXPECT_TRUE(add_study_rows(CaseResult{}, rows));
  EXPECT_TRUE(rows.empty());
}

}  // namespace
}  // namespace flume
