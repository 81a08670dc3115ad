// `flume validate --jobs N`: cases validated at once, each in a process of its own, give the
// same results.json as one after the other (same threads per run), and report.md keeps the
// order in which the cases were asked; bad input is still exit 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/flume_binary.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

namespace fs = std::filesystem;

class ValidateJobs : public test::FlumeBinaryTest {
 protected:
  // A small dam break named `name` (file name.toml) with a curve against a one-row reference.
  void write_case(const std::string& name, const std::string& preset) {
    std::string toml = test::dam_break_toml(preset, 8, 0.002);
    const std::string old_name = "name = \"small_dam_break\"";
    toml.replace(toml.find(old_name), old_name.size(), "name = \"" + name + "\"");
    std::ofstream(dir_ / (name + ".toml")) << toml << "\n[validation]\n"
                                           << test::column_height_curve_toml();
  }
  test::CliResult validate(const std::string& args) {
    return flume_env("FLUME_CASES_DIR=" + dir_.string() + " ",
                     "validate --quiet --threads 1 " + args);
  }
};

TEST_F(ValidateJobs, SameResultsAsOneAfterTheOtherInTheOrderAsked) {
  std::ofstream(dir_ / "ref.csv") << "t,height\n0.0,1.0\n";
  write_case("first", "continuity");
  write_case("second", "csph");
  write_case("third", "standard");
  const auto one = validate("third first second --out " + (dir_ / "one").string());
  ASSERT_EQ(one.status, 0) << one.err;
  const auto two = validate("third first second --jobs 2 --out " + (dir_ / "two").string());
  ASSERT_EQ(two.status, 0) << two.err;
  const std::string results = test::slurp(dir_ / "one" / "results.json");
  EXPECT_NE(results.find("\"first\""), std::string::npos);
  EXPECT_EQ(test::slurp(dir_ / "two" / "results.json"), results);
  // report.md: the sections in the order asked (third, first, second), whichever ended first.
  const std::string report = test::slurp(dir_ / "two" / "report.md");
  const auto third = report.find("\n## third\n");
  const auto first = report.find("\n## first\n");
  const auto second = report.find("\n## second\n");
  ASSERT_NE(third, std::string::npos) << report;
  ASSERT_NE(first, std::string::npos) << report;
  ASSERT_NE(second, std::string::npos) << report;
  EXPECT_LT(third, first);
  EXPECT_LT(first, second);
}

TEST_F(ValidateJobs, BadInputInAChildIsExitTwoWithItsLine) {
  std::ofstream(dir_ / "ref.csv") << "t,height\n0.0,1.0\n";
  write_case("first", "continuity");
  write_case("second", "csph");
  const auto r = validate("first second --jobs 2 --set a.b=1 --out " + (dir_ / "bad").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--set a.b: unknown key"), std::string::npos) << r.err;
  EXPECT_EQ(flume("validate first --jobs 0").status, 2);
}

}  // namespace
}  // namespace flume
