// The flume executable as a user sees it: exit status 0/1/2, one clear line for bad input, and
// the run directory of spec/contract.md, kept when the simulation fails.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include <fmt/format.h>

#include "flume/io/csv_table.hpp"
#include "support/flume_binary.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

namespace fs = std::filesystem;

using Result = test::CliResult;
using test::slurp;

class Cli : public test::FlumeBinaryTest {
 protected:
  // A run that failed: exit status 1, and `why` both on stderr and in summary.json.
  void expect_failed_run(const Result& r, const fs::path& out, const std::string& why) {
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    const auto summary = nlohmann::json::parse(slurp(out / "summary.json"));
    EXPECT_EQ(summary["status"], "failed");
    EXPECT_NE(summary["error"].get<std::string>().find(why), std::string::npos);
  }
  fs::path write_case(const std::string& toml) {
    const auto p = dir_ / "case.toml";
    std::ofstream(p) << toml;
    return p;
  }
};

TEST_F(Cli, RunWritesTheRunDirectory) {
  const auto file = write_case(test::dam_break_toml("continuity", 8, 0.02));
  const auto out = dir_ / "run";
  const auto r = flume("run " + file.string() + " --out " + out.string() +
                       " --set output.snapshot_interval=0.01 --threads 1");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* f : {"case.toml", "diagnostics.csv", "probes.csv", "summary.json", "log.txt",
                        "snapshots/snapshots.pvd", "snapshots/snapshot_00000.vtu"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const auto diag = io::read_csv(out / "diagnostics.csv");
  for (const char* c :
       {"time", "step", "dt", "particles", "mass", "momentum_x", "momentum_y", "angular_momentum",
        "kinetic_energy", "potential_energy", "internal_energy", "rho_min", "rho_max"})
    EXPECT_NO_THROW(diag.column(c)) << c;
  const auto mass = diag.column("mass");
  // Particles keep their masses: total mass constant to round-off of the serial sum.
  for (double m : mass)
    EXPECT_NEAR(m, mass.front(), 1e-14 * mass.front());
  const auto probes = io::read_csv(out / "probes.csv");
  EXPECT_EQ(probes.columns, (std::vector<std::string>{"time", "surge_front", "column_height"}));
  const auto summary = nlohmann::json::parse(slurp(out / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_TRUE(summary["error"].is_null());
  EXPECT_EQ(summary["particles"], 64);
  EXPECT_EQ(summary["threads"], 1);
  EXPECT_EQ(summary["ranks"], 1);
  for (const char* k : {"case", "steps", "simulated_time", "wall_seconds",
                        "particle_steps_per_second", "flume_version"})
    EXPECT_TRUE(summary.contains(k)) << k;
  EXPECT_NEAR(summary["simulated_time"].get<double>(), 0.02, 1e-12);
  // No temporary file is left behind by the atomic writes.
  for (const auto& e : fs::recursive_directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

// A small case asked to run on two threads steps on one (at most one thread per 1,000
// particles, sim/thread_team.hpp), says so in its log and its summary; --particles-per-thread 0
// gives it both.
TEST_F(Cli, ASmallCaseStepsOnOneThreadUnlessToldOtherwise) {
  const auto file = write_case(test::dam_break_toml("standard", 8, 0.005));
  const auto one = dir_ / "one", two = dir_ / "two";
  ASSERT_EQ(flume("run " + file.string() + " --quiet --threads 2 --out " + one.string()).status, 0);
  EXPECT_EQ(nlohmann::json::parse(slurp(one / "summary.json"))["threads"], 1);
  EXPECT_NE(slurp(one / "log.txt").find("1 thread(s) of the 2 asked"), std::string::npos)
      << slurp(one / "log.txt");
  ASSERT_EQ(flume("run " + file.string() + " --quiet --threads 2 --particles-per-thread 0 --out " +
                  two.string())
                .status,
            0);
  EXPECT_EQ(nlohmann::json::parse(slurp(two / "summary.json"))["threads"], 2);
  EXPECT_EQ(slurp(two / "log.txt").find("asked"), std::string::npos);
  EXPECT_EQ(slurp(one / "diagnostics.csv"), slurp(two / "diagnostics.csv"));
}

TEST_F(Cli, ResolvedCaseRepeatsTheRunExactly) {
  const auto file = write_case(test::dam_break_toml("standard", 8, 0.01));
  ASSERT_EQ(flume("run " + file.string() + " --quiet --out " + (dir_ / "a").string()).status, 0);
  ASSERT_EQ(flume("run " + (dir_ / "a" / "case.toml").string() + " --quiet --out " +
                  (dir_ / "b").string())
                .status,
            0);
  EXPECT_EQ(slurp(dir_ / "a" / "diagnostics.csv"), slurp(dir_ / "b" / "diagnostics.csv"));
  EXPECT_EQ(slurp(dir_ / "a" / "probes.csv"), slurp(dir_ / "b" / "probes.csv"));
}

TEST_F(Cli, BadInputExitsWithTwoAndOneLine) {
  const auto file = write_case(test::dam_break_toml("continuity", 8, 0.01));
  for (const std::string args :
       {"--set scheme.bogus=1", "--set particles.spacing=-1", "--set scheme.cfl=\\\"x\\\""}) {
    const auto r = flume("run " + file.string() + " " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(file.string()), std::string::npos) << r.err;
  }
  EXPECT_EQ(flume("run " + (dir_ / "missing.toml").string()).status, 2);
  // A negative count of particles per thread (an unsigned value: it would wrap to a huge one).
  const auto per_thread = flume("run " + file.string() + " --particles-per-thread -3");
  EXPECT_EQ(per_thread.status, 2);
  EXPECT_NE(per_thread.err.find("--particles-per-thread"), std::string::npos) << per_thread.err;
  EXPECT_EQ(flume("run").status, 2);
  EXPECT_EQ(flume("frobnicate").status, 2);
}

TEST_F(Cli, FailedSimulationExitsWithOneAndKeepsItsOutput) {
  // An open floor: the water falls out of the domain, a lost particle.
  const auto file = write_case(test::dam_break_toml("continuity", 8, 0.5));
  const auto out = dir_ / "run";
  const auto r = flume("run " + file.string() + " --out " + out.string() +
                       " --set boundaries.y_min=open --set output.interval=0.01");
  expect_failed_run(r, out, "lost");
  EXPECT_GT(io::read_csv(out / "diagnostics.csv").rows.size(), 2u);
  EXPECT_NE(slurp(out / "log.txt").find("failed"), std::string::npos);
}

TEST_F(Cli, BlowUpExitsWithOneAndSaysWhy) {
  // A fixed step 20 times the CFL limit: the density goes negative within a few steps.
  const auto file = write_case(test::dam_break_toml("continuity", 8, 0.1));
  const auto out = dir_ / "run";
  const auto r = flume("run " + file.string() + " --quiet --out " + out.string() +
                       " --set case.dt=0.005 --set output.snapshot_interval=1.0");
  expect_failed_run(r, out, "blew up");
  // The failed state is kept as the last snapshot of the series, after the one at t = 0.
  const auto pvd = slurp(out / "snapshots" / "snapshots.pvd");
  EXPECT_NE(pvd.find("snapshot_00001.vtu"), std::string::npos) << pvd;
  EXPECT_TRUE(std::filesystem::exists(out / "snapshots" / "snapshot_00001.vtu"));
  EXPECT_NE(slurp(out / "log.txt").find("failed state"), std::string::npos);
}

TEST_F(Cli, ValidateFailsOnlyOnGatedCurves) {
  // Two curves on one reference at t = 0, where both probes read exactly a: the column height,
  // compared with a, passes; the surge front, compared with 2 a, is 50 % off. Reported but not
  // gated, it leaves the validation passing; gated, it fails it with exit status 1.
  std::ofstream(dir_ / "ref.csv") << "t,height,front\n0.0,1.0,2.0\n";
  const auto validation = [](bool gated) {
    return test::column_height_curve_toml() + fmt::format(R"(tolerance = 0.01
quick_tolerance = 0.01
[[validation.curves]]
probe = "surge_front"
reference = "ref.csv"
reference_x = "t"
reference_y = "front"
value_scale = 0.05715
tolerance = 0.1
quick_tolerance = 0.1
gated = {}
)",
                                                          gated);
  };
  const std::string env = "FLUME_CASES_DIR=" + dir_.string() + " ";
  const auto out = dir_ / "validation";
  for (bool gated : {false, true}) {
    write_case(test::dam_break_toml("continuity", 8, 0.002) + validation(gated));
    const auto r = flume_env(env, "validate case --quiet --out " + out.string());
    EXPECT_EQ(r.status, gated ? 1 : 0) << r.err;
    const auto rows = nlohmann::json::parse(slurp(out / "results.json"));
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0]["pass"], true);
    EXPECT_EQ(rows[1]["pass"], false);
    EXPECT_EQ(rows[1]["gated"], gated);
    EXPECT_EQ(slurp(out / "report.md").find("reported, not gated") != std::string::npos, !gated);
  }
}

TEST_F(Cli, ValidateAppliesSetOverridesToEveryRun) {
  std::ofstream(dir_ / "ref.csv") << "t,height\n0.0,1.0\n";
  write_case(test::dam_break_toml("continuity", 8, 0.002) + R"(
[validation]
variants = ["scheme.preset=csph"]
)" + test::column_height_curve_toml());
  const std::string env = "FLUME_CASES_DIR=" + dir_.string() + " ";
  const auto out = dir_ / "validation";
  const auto r =
      flume_env(env, "validate case --quiet --out " + out.string() + " --set case.end_time=0.001");
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* run : {"continuity", "csph"}) {
    const auto summary = nlohmann::json::parse(slurp(out / "case" / run / "summary.json"));
    EXPECT_DOUBLE_EQ(summary["simulated_time"].get<double>(), 0.001) << run;
  }
  EXPECT_NE(slurp(out / "report.md").find("`case.end_time=0.001`"), std::string::npos);
  // The report's list of runs says what each variant changed.
  EXPECT_NE(slurp(out / "report.md").find("- `csph` (`scheme.preset=csph`):"), std::string::npos);
  // An unknown key is bad input, as for `flume run`.
  const auto bad = flume_env(env, "validate case --quiet --out " + out.string() + " --set a.b=1");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("a.b"), std::string::npos) << bad.err;
}

TEST_F(Cli, CasesListsTheBundledDamBreak) {
  const auto r = flume("cases");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("dam_break"), std::string::npos) << r.out;
  const auto v = flume("--version");
  EXPECT_EQ(v.status, 0);
  EXPECT_NE(v.out.find("flume"), std::string::npos);
}

}  // namespace
}  // namespace flume
