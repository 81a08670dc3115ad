// Inputs a user gets wrong, caught before a step runs: exit status 2 and one line naming the file
// or option and what is allowed (issue 9's three known cases: a spacing that needs more memory
// than the machine has, --out naming a file, a directory or a binary file given as the case).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "support/flume_binary.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

namespace fs = std::filesystem;

class HostileInput : public test::FlumeBinaryTest {
 protected:
  fs::path write_case() {
    const auto p = dir_ / "case.toml";
    std::ofstream(p) << test::dam_break_toml("continuity", 8, 0.01);
    return p;
  }
  // Exit 2, one line on stderr holding every part, and no run directory left behind.
  void expect_refused(const std::string& args, std::initializer_list<std::string> parts) {
    const auto r = flume(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const auto& p : parts)
      EXPECT_NE(r.err.find(p), std::string::npos) << p << " in: " << r.err;
  }
};

TEST_F(HostileInput, SpacingThatNeedsMoreMemoryThanTheMachineHas) {
  // 0.23 m x 0.11 m of water at 1e-8 m: ~2.5e14 particles.
  const auto file = write_case();
  const auto out = dir_ / "run";
  expect_refused("run " + file.string() + " --set particles.spacing=1e-8 --out " + out.string(),
                 {file.string(), "particles.spacing", "particles", "GB", "larger spacing"});
  EXPECT_FALSE(fs::exists(out / "diagnostics.csv"));
}

TEST_F(HostileInput, OutNamingAFileOrAnUnwritablePlace) {
  const auto file = write_case();
  const auto taken = dir_ / "a_file";
  std::ofstream(taken) << "not a folder\n";
  expect_refused("run " + file.string() + " --out " + taken.string(),
                 {"--out", taken.string(), "not a directory"});
  // A folder inside a file cannot be made.
  expect_refused("run " + file.string() + " --out " + (taken / "run").string(),
                 {"--out", "cannot create"});
}

TEST_F(HostileInput, DirectoryOrBinaryFileAsTheCase) {
  expect_refused("run " + dir_.string(), {dir_.string(), "is a directory"});
  const auto binary = dir_ / "flume.bin";
  fs::copy_file(FLUME_BINARY, binary);
  expect_refused("run " + binary.string(), {binary.string(), "binary file"});
}

}  // namespace
}  // namespace flume
