// The flume command line: turns arguments into a CaseSpec (or validation or bench options) and
// calls the library. Exit status (spec/contract.md): 0 success, 1 the simulation or a validation
// failed, 2 bad input.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "flume/bench/bench.hpp"
#include "flume/case/case_reader.hpp"
#include "flume/core/error.hpp"
#include "flume/run/runner.hpp"
#include "flume/validation/bundled_cases.hpp"
#include "flume/validation/validate.hpp"

namespace {

// The run directory must be a directory flume can write: an existing file in its place, or a
// folder that cannot be made, is bad input (exit 2, one line), found before the run starts.
void check_out_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw flume::InputError(fmt::format(
        "--out {}: exists and is not a directory; name a new or existing folder", dir.string()));
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw flume::InputError(
        fmt::format("--out {}: cannot create the run directory: {}", dir.string(), ec.message()));
  const auto probe = dir / ".flume_write_test";
  {
    std::ofstream test(probe);
    if (!test)
      throw flume::InputError(
          fmt::format("--out {}: the run directory is not writable", dir.string()));
  }
  std::filesystem::remove(probe, ec);
}

// Exit status of a run (spec/contract.md): 0 completed, 1 failed, 128 + the signal when
// interrupted (130 SIGINT, 143 SIGTERM), as a shell reports a process ended by it.
int finish(const std::string& name, const flume::RunResult& result, const flume::RunOptions& opt) {
  if (result.interrupted) {
    std::cerr << fmt::format(
        "flume: {}: interrupted; checkpoint written, continue with `flume "
        "resume {}`\n",
        name, opt.out_dir.string());
    return 128 + result.signal;
  }
  if (!result.completed) {
    std::cerr << fmt::format("flume: {}: simulation failed: {} (output kept in {})\n", name,
                             result.error, opt.out_dir.string());
    return 1;
  }
  if (!opt.quiet) std::cout << fmt::format("results: {}\n", opt.out_dir.string());
  return 0;
}

// `opt` holds the command line's threads, particles per thread and quiet.
int cmd_run(const std::string& case_file, const std::string& out,
            const std::vector<std::string>& sets, flume::RunOptions opt) {
  const flume::CaseSpec spec = flume::read_case(case_file, sets);
  opt.out_dir =
      out.empty() ? std::filesystem::path("runs") / spec.name : std::filesystem::path(out);
  check_out_dir(opt.out_dir);
  return finish(spec.name, flume::run_case(spec, opt), opt);
}

int cmd_resume(const std::string& dir, flume::RunOptions opt) {
  opt.out_dir = dir;
  if (!std::filesystem::is_directory(opt.out_dir))
    throw flume::InputError(fmt::format("{}: not a run directory", dir));
  check_out_dir(opt.out_dir);
  return finish(opt.out_dir.filename().string(), flume::resume_run(opt), opt);
}

int cmd_cases() {
  for (const auto& file : flume::bundled_case_files()) {
    const auto spec = flume::read_case(file, {});
    std::cout << fmt::format("{:<20} {}\n", spec.name, spec.description);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"flume: free-surface flow by Smoothed Particle Hydrodynamics"};
  app.set_version_flag("--version", std::string("flume ") + FLUME_VERSION);
  app.require_subcommand(1);

  auto* run = app.add_subcommand("run", "run one case");
  std::string case_file, out;
  std::vector<std::string> sets;
  flume::RunOptions ropt;
  // A count of particles, 0 or more (an unsigned option would take -3 as a huge count).
  const CLI::Validator count_check(
      [](std::string& v) {
        return v.rfind('-', 0) == 0 ? std::string("must be 0 or more (0: every thread)")
                                    : std::string();
      },
      "N >= 0");
  const std::string per_thread_help = "at most one thread per N particles (default " +
                                      std::to_string(flume::kParticlesPerThread) +
                                      "; 0: every thread at any size); results do not depend on it";
  run->add_option("case", case_file, "case file (TOML)")->required();
  run->add_option("--out", out, "run directory (default runs/<case name>)");
  run->add_option("--set", sets, "override a case-file value: KEY=VALUE (dotted TOML path)")
      ->allow_extra_args(false);
  run->add_option("--threads", ropt.threads, "OpenMP threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  run->add_option("--particles-per-thread", ropt.particles_per_thread, per_thread_help)
      ->check(count_check);
  run->add_flag("--quiet", ropt.quiet, "no progress line and no messages");

  auto* res = app.add_subcommand("resume", "continue a run from its newest valid checkpoint");
  std::string resume_dir;
  res->add_option("dir", resume_dir, "run directory (with checkpoints/)")->required();
  res->add_option("--threads", ropt.threads, "OpenMP threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  res->add_option("--particles-per-thread", ropt.particles_per_thread, per_thread_help)
      ->check(count_check);
  res->add_flag("--quiet", ropt.quiet, "no progress line and no messages");

  auto* val = app.add_subcommand("validate", "run validation cases and compare with references");
  flume::ValidateOptions vopt;
  std::string vout = "validation";
  val->add_option("names", vopt.names, "bundled case names (default: all with references)");
  val->add_flag("--quick", vopt.quick, "the reduced-resolution set that CI runs");
  val->add_option("--set", vopt.sets,
                  "override a case-file value in every run: KEY=VALUE (dotted TOML path)")
      ->allow_extra_args(false);
  val->add_option("--out", vout, "output folder (default validation/)");
  val->add_option("--threads", vopt.threads, "OpenMP threads")->check(CLI::PositiveNumber);
  val->add_option("--jobs", vopt.jobs,
                  "cases validated at once, each in its own process with cores/jobs threads "
                  "unless --threads is given (default 1)")
      ->check(CLI::PositiveNumber);
  val->add_flag("--quiet", vopt.quiet, "no messages");

  auto* ben = app.add_subcommand(
      "bench", "throughput benchmark: the dam break scaled to N particles; writes bench.json");
  flume::BenchOptions bopt;
  std::string bout = ".";
  int bsteps = 0;
  ben->add_option("--particles", bopt.particles,
                  "particle counts, e.g. 1e5 or 1e4,1e5 (default 1e4,1e5,1e6,4e6)")
      ->delimiter(',');
  ben->add_option("--preset", bopt.presets,
                  "scheme presets, e.g. csph or standard,csph (default standard,continuity,csph)")
      ->delimiter(',');
  ben->add_option("--threads", bopt.threads, "OpenMP thread counts, e.g. 1,2 (default all cores)")
      ->delimiter(',');
  auto* steps_opt =
      ben->add_option("--steps", bsteps,
                      "measured steps of every run (default 200 to 3e4 particles, 50 to 3e5, 10)");
  ben->add_option("--warmup", bopt.warmup, "steps before the clock starts (default 3)");
  ben->add_option("--repeats", bopt.repeats,
                  "timed runs of --steps steps one after the other; the median is reported "
                  "(default 3)");
  ben->add_option("--support", bopt.support, "kernel support in spacings (default 2.83)");
  ben->add_option("--out", bout, "folder of bench.json (default the current directory)");
  ben->add_flag("--quiet", bopt.quiet, "no progress lines");

  app.add_subcommand("cases", "list the bundled cases");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }

  try {
    if (run->parsed()) return cmd_run(case_file, out, sets, ropt);
    if (res->parsed()) return cmd_resume(resume_dir, ropt);
    if (ben->parsed()) {
      bopt.out_dir = bout;
      if (steps_opt->count() > 0) bopt.steps = bsteps;
      return flume::bench(bopt);
    }
    if (val->parsed()) {
      vopt.out_dir = vout;
      return flume::validate(vopt);
    }
    return cmd_cases();
  } catch (const flume::InputError& e) {
    std::cerr << "flume: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "flume: error: " << e.what() << "\n";
    return 1;
  }
}
