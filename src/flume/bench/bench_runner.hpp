// One `flume bench` run: build the case, take a few warm-up steps, then time a fixed number of
// steps a few times over (repeats, one after the other, the simulation going on) and keep the
// median repeat (as the reference step reports its median of three: a single timing on a shared
// machine takes whatever else the machine did in that second), with the seconds per phase of the
// step, the output a real run would compute, and the mean neighbour count. run_bench_isolated does
// it in a forked child to get that run's own peak memory. The result converts to and from the JSON
// object of bench.json.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "flume/case/case_spec.hpp"

namespace flume {

struct BenchConfig {
  std::string preset;
  double particles = 1e4;  // requested; the run has round(sqrt(particles))^2
  double support = 2.83;   // kernel support in spacings
  int steps = 10;          // measured steps
  int warmup = 3;          // steps taken before the clock starts, not counted
  int repeats = 3;         // timed runs of `steps` steps, one after the other; the median is kept
  int threads = 0;         // OpenMP threads; 0 = OpenMP's default (all cores)
};

struct BenchResult {
  std::string preset;
  double requested_particles = 0.0;
  std::size_t particles = 0;  // real particles of the run
  double spacing = 0.0;       // m
  double support = 0.0;       // kernel support in spacings
  double neighbours = 0.0;    // mean per particle at the end, excluding itself (real particles)
  long steps = 0;             // measured steps (of one repeat)
  long warmup = 0;
  // Wall seconds of each repeat, in order; wall_seconds and phases are the median repeat's.
  std::vector<double> repeat_seconds;
  double setup_seconds = 0.0;  // building the particles and the simulation
  double wall_seconds = 0.0;   // the measured steps, output included
  double particle_steps_per_second = 0.0;
  double interactions_per_second = 0.0;  // particle_steps_per_second * neighbours
  long peak_rss_bytes = 0;               // of the child process that ran it (0 in-process)
  double bytes_per_particle = 0.0;       // peak_rss_bytes / particles
  int threads = 1;
  // Seconds per phase over the measured steps (Simulation::phase_clock, then "output").
  std::vector<std::pair<std::string, double>> phases;
  std::string error;  // empty for a completed run
};

// Runs `config` on `spec` (from bench_case) in this process: the memory fields stay 0.
// Throws SimulationError if the simulation fails.
BenchResult run_bench(const BenchConfig& config, const CaseSpec& spec);

// Runs `config` in a forked child (see child_process.hpp) and fills in its peak memory. Never
// throws for a failed run: `error` then says what happened (the simulation's error, or the
// signal that killed the child).
BenchResult run_bench_isolated(const BenchConfig& config, const CaseSpec& spec);

// bench.json's object for one run; from_json reads it back (the child's answer to the parent).
nlohmann::ordered_json bench_result_json(const BenchResult& r);
BenchResult bench_result_from_json(const nlohmann::ordered_json& j);

}  // namespace flume
