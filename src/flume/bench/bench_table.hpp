// The table `flume bench` prints: one row per run, throughput in millions per second, and the
// split of the measured wall time between the phases of a step (one column per phase name that
// any run reported, so presets with different sweeps share one table).
#pragma once

#include <string>
#include <vector>

#include "flume/bench/bench_runner.hpp"

namespace flume {

std::string bench_table(const std::vector<BenchResult>& results);

}  // namespace flume
