// `flume bench` as a user runs it: a tiny benchmark (2000 particles, 3 steps, one thread) exits
// with 0 and writes bench.json with every key of the speed issue and sane values, the figures
// of the median repeat; bad input (an unknown preset, no particles, no repeats, an --out that
// cannot be a folder) exits with 2 and one line.
// Speed itself is never asserted: the figures depend on the machine.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/flume_binary.hpp"

namespace flume {
namespace {

namespace fs = std::filesystem;

using test::slurp;

class BenchCli : public test::FlumeBinaryTest {};

TEST_F(BenchCli, TinyRunWritesBenchJson) {
  const auto out = dir_ / "bench";
  const auto r =
      flume("bench --particles 2000 --steps 3 --preset standard --threads 1 --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("standard"), std::string::npos) << r.out;

  const auto list = nlohmann::json::parse(slurp(out / "bench.json"));
  ASSERT_TRUE(list.is_array());
  ASSERT_EQ(list.size(), 1u);
  const auto& run = list[0];
  for (const char* k :
       {"preset", "particles", "neighbours", "steps", "wall_seconds", "particle_steps_per_second",
        "interactions_per_second", "bytes_per_particle", "threads", "phases"})
    EXPECT_TRUE(run.contains(k)) << k;
  EXPECT_EQ(run["preset"], "standard");
  // 2000 requested: a square column of round(sqrt(2000))^2 = 45^2 = 2025 particles.
  const double n = run["particles"].get<double>();
  EXPECT_NEAR(n, 2000.0, 0.05 * 2000.0);
  // Support 2.83 spacings: 24 neighbours inside the lattice, fewer at the surface and walls.
  const double neighbours = run["neighbours"].get<double>();
  EXPECT_GT(neighbours, 15.0);
  EXPECT_LT(neighbours, 30.0);
  EXPECT_EQ(run["steps"], 3);
  EXPECT_EQ(run["threads"], 1);
  const double wall = run["wall_seconds"].get<double>();
  const double psps = run["particle_steps_per_second"].get<double>();
  EXPECT_GT(wall, 0.0);
  EXPECT_NEAR(psps, n * 3.0 / wall, 1e-9 * psps);
  EXPECT_NEAR(run["interactions_per_second"].get<double>(), psps * neighbours, 1e-9 * psps * 30);
  EXPECT_GT(run["bytes_per_particle"].get<double>(), 0.0);

  const auto& phases = run["phases"];
  ASSERT_TRUE(phases.is_object());
  EXPECT_FALSE(phases.empty());
  EXPECT_TRUE(phases.contains("output"));
  // The failure checks of every step have a phase of their own (issue "runs that survive").
  EXPECT_TRUE(phases.contains("checks"));
  double total = 0.0;
  for (const auto& [name, seconds] : phases.items()) {
    EXPECT_GE(seconds.get<double>(), 0.0) << name;
    total += seconds.get<double>();
  }
  // The phases are parts of the timed steps.
  EXPECT_GT(total, 0.0);
  EXPECT_LE(total, wall * 1.01);

  // Three repeats by default; the figures are the median one's.
  ASSERT_TRUE(run.contains("repeat_wall_seconds"));
  auto repeats = run["repeat_wall_seconds"].get<std::vector<double>>();
  ASSERT_EQ(repeats.size(), 3u);
  std::sort(repeats.begin(), repeats.end());
  EXPECT_EQ(wall, repeats[1]);
}

TEST_F(BenchCli, RepeatsReportTheMedianRepeat) {
  const auto out = dir_ / "bench";
  const auto r = flume(
      "bench --particles 2000 --steps 2 --repeats 5 --preset standard --threads 1 "
      "--quiet --out " +
      out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto run = nlohmann::json::parse(slurp(out / "bench.json")).at(0);
  auto repeats = run.at("repeat_wall_seconds").get<std::vector<double>>();
  ASSERT_EQ(repeats.size(), 5u);
  for (double s : repeats)
    EXPECT_GT(s, 0.0);
  std::sort(repeats.begin(), repeats.end());
  // Exactly the middle one of the five (not a mean, not the first).
  EXPECT_EQ(run.at("wall_seconds").get<double>(), repeats[2]);
  EXPECT_EQ(run.at("steps"), 2);
}

TEST_F(BenchCli, BadInputExitsWithTwoAndOneLine) {
  std::ofstream(dir_ / "a_file") << "x";
  for (const std::string& args :
       std::vector<std::string>{"--preset bogus", "--particles 0", "--repeats 0",
                                "--out " + (dir_ / "a_file" / "sub").string()}) {
    const auto r = flume("bench --steps 1 --particles 2000 --threads 1 " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const auto r = flume("bench --preset bogus --out " + dir_.string());
  EXPECT_NE(r.err.find("bogus"), std::string::npos) << r.err;
  // Nothing ran, so nothing was written.
  EXPECT_FALSE(fs::exists(dir_ / "bench.json"));
}

}  // namespace
}  // namespace flume
