// The whole run directory does not depend on the thread count: the flume executable, run with
// --threads 1 and --threads 2 on the same case, writes byte-identical diagnostics.csv,
// probes.csv and snapshots (every file of snapshots/). The case switches on every optional path
// of a step that could order floating-point sums differently: physical viscosity (velocity
// gradient and stress sweeps, BL (22)-(24)), artificial viscosity W (3.18), no-slip mirror walls
// on all four sides (W 6.1: ghosts with reversed velocities), the Shepard density filter W (6.3)
// every 5 steps, the CFL time step (a min reduction), and the periodic re-sort by cell.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "support/flume_binary.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

namespace fs = std::filesystem;

using test::slurp;

class ThreadIdenticalRuns : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("flume_threads_" + GetParam());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs the case with `threads` OpenMP threads into dir_/name; returns the exit status.
  int run(const fs::path& case_file, int threads, const std::string& name) {
    const std::string cmd = std::string(FLUME_BINARY) + " run " + case_file.string() +
                            " --quiet --particles-per-thread 0 --threads " +
                            std::to_string(threads) + " --out " + (dir_ / name).string() + " > " +
                            (dir_ / (name + ".log")).string() + " 2>&1";
    const int raw = std::system(cmd.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  }
  fs::path dir_;
};

TEST_P(ThreadIdenticalRuns, OneAndTwoThreadsWriteIdenticalRunDirectories) {
  // The dam break of BL 5.3 at 10 x 10 particles, mu = 0.5 Pa s, for 0.04 s (~190 steps).
  const auto case_file = dir_ / "case.toml";
  std::ofstream(case_file) << test::dam_break_toml(GetParam(), 10, 0.04) << R"(
[boundaries]
x_min = "no_slip"
x_max = "no_slip"
y_min = "no_slip"
y_max = "no_slip"
)";
  // Keys of tables the case text already has are set on the command line instead.
  const std::string sets =
      " --set scheme.shepard_every=5 --set scheme.alpha=0.1 --set output.interval=0.005"
      " --set output.snapshot_interval=0.01";
  const auto with_sets = dir_ / "with_sets.toml";
  ASSERT_EQ(std::system((std::string(FLUME_BINARY) + " run " + case_file.string() + sets +
                         " --quiet --threads 1 --out " + (dir_ / "one").string() + " > " +
                         (dir_ / "one.log").string() + " 2>&1")
                            .c_str()),
            0)
      << slurp(dir_ / "one.log");
  // The resolved case.toml of the first run holds every value: running it again with two
  // threads is the same case (the resolved file repeats a run exactly, README).
  ASSERT_EQ(run(dir_ / "one" / "case.toml", 2, "two"), 0) << slurp(dir_ / "two.log");
  (void)with_sets;

  const auto one = dir_ / "one", two = dir_ / "two";
  const auto summary = nlohmann::json::parse(slurp(one / "summary.json"));
  ASSERT_EQ(summary["status"], "completed");
  EXPECT_EQ(summary["threads"], 1);
  EXPECT_EQ(nlohmann::json::parse(slurp(two / "summary.json"))["threads"], 2);
  // The Shepard filter ran many times and the diagnostics have rows to compare.
  EXPECT_GT(summary["steps"].get<long>(), 50);
  for (const char* f : {"diagnostics.csv", "probes.csv"}) {
    const auto a = slurp(one / f), b = slurp(two / f);
    EXPECT_GT(std::count(a.begin(), a.end(), '\n'), 8) << f;
    EXPECT_TRUE(a == b) << f << " differs between 1 and 2 threads";
  }
  std::set<std::string> names_one, names_two;
  for (const auto& e : fs::directory_iterator(one / "snapshots"))
    names_one.insert(e.path().filename().string());
  for (const auto& e : fs::directory_iterator(two / "snapshots"))
    names_two.insert(e.path().filename().string());
  EXPECT_EQ(names_one, names_two);
  EXPECT_GE(names_one.size(), 6u);  // snapshots.pvd and t = 0, 0.01, ..., 0.04
  for (const auto& name : names_one)
    EXPECT_TRUE(slurp(one / "snapshots" / name) == slurp(two / "snapshots" / name))
        << name << " differs between 1 and 2 threads";
}

// Both continuity-density presets (the Shepard filter needs one): BL (4) + (20) and CSPH.
INSTANTIATE_TEST_SUITE_P(Presets, ThreadIdenticalRuns, ::testing::Values("continuity", "csph"));

}  // namespace
}  // namespace flume
