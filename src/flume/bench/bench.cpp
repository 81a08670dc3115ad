#include "flume/bench/bench.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <fstream>
#include <iostream>
#include <system_error>

#include "flume/bench/bench_case.hpp"
#include "flume/bench/bench_runner.hpp"
#include "flume/bench/bench_table.hpp"
#include "flume/core/error.hpp"
#include "flume/io/atomic_file.hpp"

namespace flume {

namespace {

std::string threads_label(int threads) {
  return threads > 0 ? fmt::format("{} thread(s)", threads) : std::string("all cores");
}

// Fails before any run rather than after minutes of them: the folder must exist or be
// creatable, and accept a file.
void check_writable(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError(
        fmt::format("bench: --out {}: cannot create the folder: {}", dir.string(), ec.message()));
  const auto probe = dir / fmt::format(".flume-bench-write-test-{}", ::getpid());
  const bool ok = static_cast<bool>(std::ofstream(probe) << "x");
  std::filesystem::remove(probe, ec);
  if (!ok)
    throw InputError(fmt::format("bench: --out {}: cannot write a file there", dir.string()));
}

struct Planned {
  BenchConfig config;
  CaseSpec spec;
};

}  // namespace

int bench(const BenchOptions& options) {
  const std::vector<double> sizes =
      options.particles.empty() ? std::vector<double>{1e4, 1e5, 1e6, 4e6} : options.particles;
  const std::vector<std::string> presets =
      options.presets.empty() ? std::vector<std::string>{"standard", "continuity", "csph"}
                              : options.presets;
  const std::vector<int> threads = options.threads.empty() ? std::vector<int>{0} : options.threads;
  if (options.steps && *options.steps < 1)
    throw InputError(fmt::format("bench: --steps {}: must be positive", *options.steps));
  if (options.repeats < 1)
    throw InputError(fmt::format("bench: --repeats {}: must be positive", options.repeats));
  if (options.warmup < 0)
    throw InputError(fmt::format("bench: --warmup {}: must be >= 0", options.warmup));
  for (int t : options.threads)
    if (t < 1) throw InputError(fmt::format("bench: --threads {}: must be positive", t));

  // Resolve every case first: a bad preset or size is reported before anything runs. The
  // parent process only reads case files; all simulation happens in the children.
  std::vector<Planned> plan;
  for (const auto& preset : presets)
    for (double n : sizes) {
      const CaseSpec spec = bench_case(preset, n, options.support);
      for (int t : threads) {
        BenchConfig c;
        c.preset = preset;
        c.particles = n;
        c.support = options.support;
        c.steps = options.steps ? *options.steps : bench_default_steps(n);
        c.warmup = options.warmup;
        c.repeats = options.repeats;
        c.threads = t;
        plan.push_back({c, spec});
      }
    }
  check_writable(options.out_dir);

  std::vector<BenchResult> done;
  std::vector<std::string> failures;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const auto& c = plan[i].config;
    const std::string what = fmt::format("preset {}, {} particles requested, {}", c.preset,
                                         c.particles, threads_label(c.threads));
    if (!options.quiet)
      std::cerr << fmt::format("flume bench: [{}/{}] {}: {} x {} steps after {} warm-up ... ",
                               i + 1, plan.size(), what, c.repeats, c.steps, c.warmup)
                << std::flush;
    BenchResult r = run_bench_isolated(c, plan[i].spec);
    if (!options.quiet)
      std::cerr << (r.error.empty() ? fmt::format("median {:.3g} s\n", r.wall_seconds)
                                    : std::string("failed\n"));
    if (r.error.empty()) {
      done.push_back(std::move(r));
    } else {
      failures.push_back(fmt::format("flume bench: run failed ({}): {}", what, r.error));
    }
  }

  if (!done.empty()) std::cout << bench_table(done) << std::flush;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& r : done)
    list.push_back(bench_result_json(r));
  const auto file = options.out_dir / "bench.json";
  io::write_file_atomic(file, list.dump(2) + "\n");
  if (!options.quiet) std::cout << fmt::format("results: {}\n", file.string());
  for (const auto& f : failures)
    std::cerr << f << "\n";
  return failures.empty() ? 0 : 1;
}

}  // namespace flume
