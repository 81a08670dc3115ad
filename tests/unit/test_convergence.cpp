// Unit tests of the convergence study's pieces (src/flume/validation/convergence.*,
// density_range.*): the coarser twin's overrides, the observed order log2(coarse / fine), and the
// density range over a run, each against values worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "flume/case/case_reader.hpp"
#include "flume/validation/bundled_cases.hpp"
#include "flume/validation/convergence.hpp"
#include "flume/validation/convergence_rows.hpp"
#include "flume/validation/density_range.hpp"

namespace flume {
namespace {

TEST(Convergence, CoarserTwinDoublesEveryLatticeSpacing) {
  CaseSpec spec;
  spec.spacing = 0.01;
  spec.blocks.resize(3);
  spec.blocks[0].spacing = 0.005;
  spec.blocks[1].spacing = 0.0;  // follows particles.spacing: no override of its own
  spec.blocks[2].spacing = 0.25;
  // Doubling a double is exact and commutes with rounding a decimal, so twice double(0.01) is
  // double(0.02) and its shortest round-trip text is "0.02".
  const std::vector<std::string> expected{"particles.spacing=0.02", "fluid_blocks[0].spacing=0.01",
                                          "fluid_blocks[2].spacing=0.5"};
  EXPECT_EQ(coarser_overrides(spec), expected);
}

TEST(Convergence, WholeNumberSpacingStaysATomlFloat) {
  // 2 x 0.5 = 1 would print as "1", a TOML integer, which a float key may refuse.
  CaseSpec spec;
  spec.spacing = 0.5;
  spec.blocks.resize(1);
  EXPECT_EQ(coarser_overrides(spec), std::vector<std::string>{"particles.spacing=1.0"});
}

TEST(Convergence, RandomBlockHasNoCoarserTwin) {
  // A random block's resolution is its particle count: doubling its spacing would not coarsen it.
  CaseSpec spec;
  spec.spacing = 0.01;
  spec.blocks.resize(2);
  spec.blocks[1].layout = "random";
  EXPECT_TRUE(coarser_overrides(spec).empty());
}

TEST(Convergence, CoarserTwinOfTheShockTubeReadsBack) {
  // The overrides are applied through the case reader like any --set: the equal-mass shock tube
  // keeps equal masses (both lattices doubled) at spacings 0.02 and 0.02 / sqrt(2).
  const auto file = bundled_case("shock_tube_1to2");
  const CaseSpec fine = read_case(file, {});
  const CaseSpec coarse = read_case(file, coarser_overrides(fine));
  EXPECT_EQ(coarse.spacing, 2.0 * fine.spacing);
  ASSERT_EQ(coarse.blocks.size(), fine.blocks.size());
  EXPECT_EQ(coarse.blocks[0].spacing, 2.0 * fine.blocks[0].spacing);
  EXPECT_EQ(coarse.blocks[1].spacing, 0.0);
}

TEST(Convergence, ObservedOrderIsLog2OfTheRatio) {
  EXPECT_DOUBLE_EQ(observed_order(0.04, 0.02), 1.0);   // halves: first order
  EXPECT_DOUBLE_EQ(observed_order(0.08, 0.02), 2.0);   // quarters: second order
  EXPECT_DOUBLE_EQ(observed_order(0.03, 0.03), 0.0);   // no change
  EXPECT_DOUBLE_EQ(observed_order(0.01, 0.04), -2.0);  // grows four-fold: diverging
  // 0.05 / 0.0353553... = sqrt(2): order one half, the L1 rate across a contact discontinuity.
  EXPECT_NEAR(observed_order(0.05, 0.05 / std::sqrt(2.0)), 0.5, 1e-15);
}

TEST(Convergence, ObservedOrderOfUnusableErrorsIsNaN) {
  EXPECT_TRUE(std::isnan(observed_order(0.0, 0.01)));
  EXPECT_TRUE(std::isnan(observed_order(0.01, 0.0)));
  EXPECT_TRUE(std::isnan(observed_order(-0.01, 0.01)));
  EXPECT_TRUE(std::isnan(observed_order(HUGE_VAL, 0.01)));
  EXPECT_TRUE(std::isnan(observed_order(0.01, std::nan(""))));
}

io::CsvData diagnostics(const std::vector<std::vector<double>>& rho_min_max) {
  io::CsvData d;
  d.columns = {"time", "rho_min", "rho_max"};
  double t = 0.0;
  for (const auto& r : rho_min_max) {
    d.rows.push_back({t, r.at(0), r.at(1)});
    t += 0.1;
  }
  return d;
}

TEST(DensityRange, ExtremesOverEveryRowRelativeToRho0) {
  // The highest rho_max (1030, row 2) and the lowest rho_min (985, row 1) need not share a row,
  // nor be the first or last: (1030 - 1000) / 1000 = +3 %, (985 - 1000) / 1000 = -1.5 %. Both are
  // one correctly rounded division of whole numbers, so they equal the decimal literals exactly.
  const auto r =
      density_range(diagnostics({{995, 1010}, {985, 1005}, {990, 1030}, {998, 1002}}), 1000.0);
  EXPECT_EQ(r.above, 0.03);
  EXPECT_EQ(r.below, -0.015);
}

TEST(DensityRange, CompressedEverywhereGivesAPositiveLowerBound) {
  // A liquid squeezed above rho0 throughout: the lower extreme is above rho0 too.
  const auto r = density_range(diagnostics({{1001, 1020}, {1002, 1010}}), 1000.0);
  EXPECT_EQ(r.above, 0.02);
  EXPECT_EQ(r.below, 0.001);
}

TEST(DensityRange, RefusesWhatItCannotMeasure) {
  EXPECT_THROW(density_range(diagnostics({}), 1000.0), std::invalid_argument);
  EXPECT_THROW(density_range(diagnostics({{990, 1010}}), 0.0), std::invalid_argument);
  io::CsvData no_columns;
  no_columns.columns = {"time"};
  no_columns.rows = {{0.0}};
  EXPECT_THROW(density_range(no_columns, 1000.0), std::out_of_range);
}

// A profile case of two schemes with one gated field (rho) and one reported (u).
CaseResult two_scheme_case(std::vector<double> a_fine, std::vector<double> a_coarse,
                           std::vector<double> b_fine, std::vector<double> b_coarse) {
  CaseResult cr;
  cr.spec.name = "tube";
  cr.spec.spacing = 0.01;
  cr.coarse_spacing = 0.02;
  cr.spec.profiles.resize(2);
  cr.spec.profiles[0].field = "rho";
  cr.spec.profiles[1].field = "u";
  cr.spec.profiles[1].gated = false;
  cr.series.resize(2);
  cr.series[0].label = "a";
  cr.series[1].label = "b";
  for (auto* s : {&cr.series[0], &cr.series[1]})
    s->run.completed = s->coarse_run.completed = true;
  cr.series[0].profile_errors = std::move(a_fine);
  cr.series[0].coarse_profile_errors = std::move(a_coarse);
  cr.series[1].profile_errors = std::move(b_fine);
  cr.series[1].coarse_profile_errors = std::move(b_coarse);
  return cr;
}

TEST(ConvergenceRows, OneRowPerSchemeAndFieldWithTheRatio) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  // Every error falls: a's rho halves (ratio 0.5), b's falls by a quarter (0.75).
  EXPECT_TRUE(add_convergence_rows(
      two_scheme_case({0.01, 0.1}, {0.02, 0.2}, {0.03, 0.1}, {0.04, 0.2}), rows));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0]["value"].get<double>(), 0.01);
  EXPECT_EQ(rows[0]["reference"].get<double>(), 0.02);
  EXPECT_EQ(rows[0]["error"].get<double>(), 0.5);
  EXPECT_EQ(rows[2]["error"].get<double>(), 0.03 / 0.04);
  for (const auto& r : rows)
    EXPECT_TRUE(r["pass"].get<bool>());
}

TEST(ConvergenceRows, AGatedErrorThatDoesNotFallFailsValidation) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  // b's rho stays at 3 %: ratio 1, not below it.
  EXPECT_FALSE(add_convergence_rows(
      two_scheme_case({0.01, 0.1}, {0.02, 0.2}, {0.03, 0.1}, {0.03, 0.2}), rows));
  EXPECT_FALSE(rows[2]["pass"].get<bool>());
}

TEST(ConvergenceRows, AReportedFieldThatGrowsFailsOnlyItsRow) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  // a's u grows (0.2 -> 0.3) but u is not gated: its row fails, validation does not.
  EXPECT_TRUE(add_convergence_rows(
      two_scheme_case({0.01, 0.3}, {0.02, 0.2}, {0.03, 0.1}, {0.04, 0.2}), rows));
  EXPECT_FALSE(rows[1]["pass"].get<bool>());
  EXPECT_FALSE(rows[1]["gated"].get<bool>());
}

TEST(ConvergenceRows, AFailedCoarseRunOfTheCaseAsWrittenFailsValidation) {
  auto cr = two_scheme_case({0.01, 0.1}, {}, {0.03, 0.1}, {0.04, 0.2});
  cr.series[0].coarse_run.completed = false;
  cr.series[0].coarse_run.error = "density below zero";
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  EXPECT_FALSE(add_convergence_rows(cr, rows));
  EXPECT_TRUE(rows[0]["value"].is_null());
  EXPECT_EQ(rows[0]["error"].get<std::string>(), "density below zero");
  EXPECT_TRUE(rows[0]["gated"].get<bool>());
}

TEST(ConvergenceRows, AFailedVariantRunIsReportedNotGated) {
  // As everywhere else a variant's run is reported beside the case, not gated: its rows fail and
  // say why, validation does not.
  auto cr = two_scheme_case({0.01, 0.1}, {0.02, 0.2}, {}, {0.04, 0.2});
  cr.series[1].run.completed = false;
  cr.series[1].run.error = "blew up";
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  EXPECT_TRUE(add_convergence_rows(cr, rows));
  EXPECT_FALSE(rows[2]["pass"].get<bool>());
  EXPECT_FALSE(rows[2]["gated"].get<bool>());
  EXPECT_EQ(rows[2]["error"].get<std::string>(), "blew up");
}

TEST(ConvergenceRows, NoCoarserRunsNoRows) {
  auto cr = two_scheme_case({0.01, 0.1}, {0.02, 0.2}, {0.03, 0.1}, {0.04, 0.2});
  cr.coarse_spacing = 0.0;
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  EXPECT_TRUE(add_convergence_rows(cr, rows));
  EXPECT_TRUE(rows.empty());
}

}  // namespace
}  // namespace flume
