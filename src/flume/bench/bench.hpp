// `flume bench`: the throughput benchmark of the speed issue. Runs the bundled dam break scaled
// to each requested particle count, for each preset and thread count asked, each in its own
// child process; prints a table and writes bench.json (a list with one object per completed
// run, see bench_runner.hpp for its keys).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace flume {

struct BenchOptions {
  std::vector<double> particles;     // empty = 1e4, 1e5, 1e6, 4e6
  std::vector<std::string> presets;  // empty = standard, continuity, csph
  std::vector<int> threads;          // empty = OpenMP's default (all cores)
  std::optional<int> steps;          // measured steps of every run; none = by size
  int warmup = 3;                    // steps before the clock starts
  int repeats = 3;                   // timed runs of `steps` steps; the median one is reported
  double support = 2.83;             // kernel support in spacings (DualSPHysics's 2h)
  std::filesystem::path out_dir = ".";
  bool quiet = false;  // no progress lines on stderr
};

// Returns the exit status: 0 when every run completed, 1 when one failed (each named on stderr;
// bench.json still holds the others). Throws InputError for bad options (exit status 2) before
// running anything.
int bench(const BenchOptions& options);

}  // namespace flume
