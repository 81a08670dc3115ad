// The paddle tank (cases/paddle_tank.toml: a piston-flap paddle W (6.9) and a beach, both walls of
// repulsive boundary particles with the Monaghan-Kos force, their put-back W (6.8), the RK2 step,
// the Shepard filter) writes byte-identical probes.csv and diagnostics.csv with 1 and 2 threads:
// the walls' forces are summed per particle over the walls in a fixed order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/flume_binary.hpp"

namespace flume {
namespace {

namespace fs = std::filesystem;

TEST(ThreadIdenticalPaddle, OneAndTwoThreadsWriteIdenticalProbesAndDiagnostics) {
  const fs::path dir = fs::temp_directory_path() / "flume_threads_paddle";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string case_file = std::string(FLUME_SOURCE_DIR) + "/cases/paddle_tank.toml";
  // 0.15 s at the quick resolution (120 RK2 steps): the paddle has started its stroke.
  const std::string sets =
      " --set particles.spacing=0.025 --set case.dt=1.25e-4 --set case.end_time=0.15"
      " --set output.interval=0.01 --set output.snapshot_interval=0.0";
  for (int threads : {1, 2}) {
    const std::string name = "t" + std::to_string(threads);
    const std::string cmd = std::string(FLUME_BINARY) + " run " + case_file + sets +
                            " --quiet --particles-per-thread 0 --threads " +
                            std::to_string(threads) + " --out " + (dir / name).string() + " > " +
                            (dir / (name + ".log")).string() + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << test::slurp(dir / (name + ".log"));
  }
  for (const char* f : {"diagnostics.csv", "probes.csv"}) {
    const auto a = test::slurp(dir / "t1" / f), b = test::slurp(dir / "t2" / f);
    EXPECT_GT(std::count(a.begin(), a.end(), '\n'), 10) << f;
    EXPECT_TRUE(a == b) << f << " differs between 1 and 2 threads";
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace flume
