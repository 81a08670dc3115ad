// Running a case to its end time and writing its run directory (spec/contract.md): case.toml,
// diagnostics.csv, probes.csv, snapshots/ (.pvd + .vtu), summary.json, log.txt, each written
// atomically. A failed simulation keeps everything written so far and says why in summary.json.
// Checkpoints (run/checkpoint.hpp) as the case's [checkpoint] asks, and on SIGINT / SIGTERM.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "flume/case/case_spec.hpp"
#include "flume/sim/thread_team.hpp"

namespace flume {

struct RunOptions {
  std::filesystem::path out_dir;  // run directory
  int threads = 0;                // 0 = OpenMP's default
  bool quiet = false;             // no progress line, no messages on stdout
  // The steps run on at most one thread per this many real particles; 0: on every thread
  // (sim/thread_team.hpp).
  std::size_t particles_per_thread = kParticlesPerThread;
};

struct RunResult {
  bool completed = false;
  bool interrupted = false;  // by SIGINT or SIGTERM (signal): a checkpoint was written
  int signal = 0;
  std::string error;  // empty when completed or interrupted
  std::size_t particles = 0;
  long steps = 0;
  double simulated_time = 0.0;
  double wall_seconds = 0.0;
  double particle_steps_per_second = 0.0;
  int threads = 1;
};

// Runs the case; never throws for a failed simulation (see RunResult), only for I/O errors.
RunResult run_case(const CaseSpec& spec, const RunOptions& options);

// Continues the run in options.out_dir from its newest checkpoint that reads back whole (each
// one that does not is named in a line of the log, with why); the rest of the run is
// bit-identical to one never interrupted. Throws InputError when there is none.
RunResult resume_run(const RunOptions& options);

}  // namespace flume
