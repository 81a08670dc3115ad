#include "flume/run/runner.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "flume/case/build_simulation.hpp"
#include "flume/case/case_reader.hpp"
#include "flume/core/error.hpp"
#include "flume/io/atomic_file.hpp"
#include "flume/run/case_probes.hpp"
#include "flume/run/checkpoint.hpp"
#include "flume/run/interrupts.hpp"
#include "flume/run/profile.hpp"
#include "flume/run/run_output.hpp"
#include "flume/sim/diagnostics.hpp"
#include "flume/sim/state_fields.hpp"

namespace flume {

namespace {

using Clock = std::chrono::steady_clock;

template <int D>
io::PointCloud snapshot_cloud(const ParticleSet<D>& ps) {
  io::PointCloud cloud;
  const std::size_t n = ps.n_real;
  cloud.xyz.resize(3 * n, 0.0);
  io::PointField vel{"velocity", 3, std::vector<double>(3 * n, 0.0)};
  io::PointField rho{"density", 1, {}}, p{"pressure", 1, {}}, m{"mass", 1, {}};
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) {
      cloud.xyz[3 * i + k] = ps.x[i][k];
      vel.data[3 * i + k] = ps.v[i][k];
    }
    rho.data.push_back(ps.rho[i]);
    p.data.push_back(ps.p[i]);
    m.data.push_back(ps.m[i]);
    cloud.ids.push_back(ps.id[i]);
  }
  cloud.fields = {std::move(vel), std::move(rho), std::move(p), std::move(m)};
  if (ps.uses(kFieldEnergy))
    cloud.fields.push_back(
        {"internal_energy", 1, std::vector<double>(ps.e.begin(), ps.e.begin() + n)});
  if (ps.uses(kFieldL))  // how far BL (41) is from holding before the correction matrix
    cloud.fields.push_back(
        {"bl41_deviation", 1,
         std::vector<double>(ps.bl41_deviation.begin(), ps.bl41_deviation.begin() + n)});
  return cloud;
}

// The in-place progress line: simulated time, percent, steps per second, ETA.
class Progress {
 public:
  Progress(bool enabled, double end_time) : enabled_(enabled), end_(end_time) {}
  void update(double t, long steps, double wall) {
    if (!enabled_ || wall - last_ < 0.25) return;
    last_ = wall;
    const double frac = t / end_;
    const double eta = frac > 0.0 ? wall * (1.0 - frac) / frac : 0.0;
    std::fprintf(stdout, "\r  t = %.4g s  %5.1f %%  %.0f steps/s  ETA %.0f s   ", t, 100.0 * frac,
                 static_cast<double>(steps) / std::max(wall, 1e-9), eta);
    std::fflush(stdout);
  }
  void finish() {
    if (enabled_) std::fprintf(stdout, "\r%78s\r", "");
  }

 private:
  bool enabled_;
  double end_;
  double last_ = -1.0;
};

void write_summary(const std::filesystem::path& dir, const CaseSpec& spec, const RunResult& r) {
  nlohmann::ordered_json j;
  j["case"] = spec.name;
  j["status"] = r.completed ? "completed" : r.interrupted ? "interrupted" : "failed";
  j["error"] = r.error.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.error);
  j["particles"] = r.particles;
  j["steps"] = r.steps;
  j["simulated_time"] = r.simulated_time;
  j["wall_seconds"] = r.wall_seconds;
  j["particle_steps_per_second"] = r.particle_steps_per_second;
  j["threads"] = r.threads;
  j["ranks"] = 1;
  j["flume_version"] = FLUME_VERSION;
  io::write_file_atomic(dir / "summary.json", j.dump(2) + "\n");
}

// The real particles' state fields, the rest left empty: what a checkpoint holds.
template <int D>
ParticleSet<D> state_of(const ParticleSet<D>& ps) {
  ParticleSet<D> out;
  out.optional = ps.optional;
  out.n_real = ps.n_real;
  copy_state_fields(ps, out, ps.n_real);
  return out;
}

// A run from the start (from = null) or from a checkpoint.
template <int D>
RunResult run_dim(const CaseSpec& spec, const RunOptions& opt, const Checkpoint<D>* from,
                  const std::vector<std::string>& notes) {
  RunResult result;
  result.threads = omp_get_max_threads();
  const auto start = Clock::now();
  auto wall = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  const InterruptHandlers interrupts;

  std::filesystem::create_directories(opt.out_dir);
  io::write_file_atomic(opt.out_dir / "case.toml", spec.resolved_toml);
  RunOutput out(opt.out_dir, diagnostics_columns<D>(), CaseProbes<D>(spec).columns(), opt.quiet,
                from ? &from->output : nullptr);
  for (const auto& line : notes)
    out.log(line);
  const bool tty = isatty(fileno(stdout)) != 0;
  Progress progress(tty && !opt.quiet, spec.end_time);

  std::unique_ptr<Simulation<D>> sim;
  CaseProbes<D> probes(spec);
  try {
    sim = std::make_unique<Simulation<D>>(build_simulation<D>(spec));
    sim->set_particles_per_thread(opt.particles_per_thread);
    if (from) sim->restore(from->particles, from->state);
  } catch (const SimulationError& e) {
    result.error = e.what();
  }
  long steps_before = 0;
  if (sim) {
    result.particles = sim->particles().n_real;
    // The threads the steps run on: fewer than asked for a small case (thread_team.hpp).
    const int asked = result.threads;
    result.threads = sim->step_threads();
    const std::string fewer = result.threads < asked
                                  ? fmt::format(
                                        " of the {} asked (at most one per {} particles: "
                                        "--particles-per-thread)",
                                        asked, opt.particles_per_thread)
                                  : "";
    out.log(
        fmt::format("flume {}: case {} ({}D), {} particles, scheme {} ({} density + {} force, "
                    "correction {}), kernel {}, {} thread(s){}",
                    FLUME_VERSION, spec.name, D, result.particles, spec.preset, spec.density,
                    spec.force, spec.correction, spec.kernel, result.threads, fewer));
    out.log(fmt::format("  c0 = {:.4g} m/s, kappa = {:.4g} Pa, h = {:.4g} m, end time {} s",
                        spec.sound_speed, spec.bulk_modulus, spec.h_over_dx * spec.spacing,
                        spec.end_time));
    auto record = [&] {
      out.add_diagnostics(diagnostics_row(sim->particles(), sim->physics(), sim->time(),
                                          sim->steps(), sim->last_dt()));
      out.add_probes(probes.row(*sim));
    };
    long next_output = 1, next_snapshot = 1;
    if (from) {
      next_output = static_cast<long>(from->output.next_output);
      next_snapshot = static_cast<long>(from->output.next_snapshot);
      probes.restore(from->output.probe_state);
      out.log(fmt::format("resumed at step {}, t = {:.6g} s", sim->steps(), sim->time()));
    } else {
      record();
      if (spec.snapshot_interval > 0.0) out.add_snapshot(0.0, snapshot_cloud(sim->particles()));
    }
    out.flush();
    steps_before = sim->steps();
    // Everything the run's files and the loop below need to go on from this step.
    auto checkpoint = [&] {
      out.flush();  // the rows the checkpoint counts are on disk
      Checkpoint<D> c;
      c.case_toml = spec.resolved_toml;
      c.case_name = spec.name;
      c.state = sim->state();
      c.output.next_output = next_output;
      c.output.next_snapshot = next_snapshot;
      c.output.diagnostics_rows = static_cast<std::int64_t>(out.diagnostics_rows());
      c.output.probe_rows = static_cast<std::int64_t>(out.probe_rows());
      c.output.snapshot_times = out.snapshot_times();
      c.output.probe_state = probes.state();
      c.particles = state_of(sim->particles());
      write_checkpoint(checkpoint_path(opt.out_dir, sim->steps()), c);
      prune_checkpoints(opt.out_dir, spec.checkpoint_keep);
    };
    double last_checkpoint = wall();
    // A step never overshoots the end; output happens at the first step at or past each
    // output time (times are recorded exactly in the files).
    const double eps = 1e-12 * spec.end_time;
    try {
      while (sim->time() < spec.end_time - eps) {
        sim->step(spec.end_time - sim->time());
        const bool last = sim->time() >= spec.end_time - eps;
        if (last || sim->time() >= static_cast<double>(next_output) * spec.output_interval - eps) {
          record();
          while (static_cast<double>(next_output) * spec.output_interval <= sim->time() + eps)
            ++next_output;
          out.flush();
        }
        if (spec.snapshot_interval > 0.0 &&
            (last ||
             sim->time() >= static_cast<double>(next_snapshot) * spec.snapshot_interval - eps)) {
          out.add_snapshot(sim->time(), snapshot_cloud(sim->particles()));
          while (static_cast<double>(next_snapshot) * spec.snapshot_interval <= sim->time() + eps)
            ++next_snapshot;
        }
        progress.update(sim->time(), sim->steps(), wall());
        if (const int sig = InterruptHandlers::pending(); sig != 0 && !last) {
          checkpoint();
          result.interrupted = true;
          result.signal = sig;
          out.log(
              fmt::format("interrupted by {} at step {}, t = {:.6g} s: checkpoint written; "
                          "continue with `flume resume {}`",
                          sig == SIGINT ? "SIGINT" : "SIGTERM", sim->steps(), sim->time(),
                          opt.out_dir.string()));
          break;
        }
        const bool by_steps =
            spec.checkpoint_every_steps > 0 && sim->steps() % spec.checkpoint_every_steps == 0;
        const bool by_time = spec.checkpoint_every_seconds > 0.0 &&
                             wall() - last_checkpoint >= spec.checkpoint_every_seconds;
        if (!last && (by_steps || by_time)) {
          checkpoint();
          last_checkpoint = wall();
        }
      }
      result.completed = !result.interrupted;
      if (result.completed && spec.profile)
        write_profile(opt.out_dir / "profile.csv", sim->particles(), spec.profile_axis,
                      spec.profile_at, spec.profile_band * spec.spacing);
    } catch (const SimulationError& e) {
      result.error = e.what();
      // The state that failed, as the series' last snapshot: where it blew up is the first
      // thing a user wants to see. Written after the error is recorded, so that a write
      // failure cannot hide it.
      out.add_snapshot(sim->time(), snapshot_cloud(sim->particles()));
      out.log(fmt::format("the failed state at t = {:.6g} s is the last snapshot", sim->time()));
    }
    progress.finish();
    result.steps = sim->steps();
    result.simulated_time = sim->time();
  }
  result.wall_seconds = wall();
  // The rate of this process's steps (a resumed run counts those after the checkpoint).
  result.particle_steps_per_second = result.wall_seconds > 0.0
                                         ? static_cast<double>(result.particles) *
                                               static_cast<double>(result.steps - steps_before) /
                                               result.wall_seconds
                                         : 0.0;
  if (result.completed) {
    out.log(fmt::format("completed: {} steps to t = {:.6g} s in {:.2f} s ({:.3g} particle-steps/s)",
                        result.steps, result.simulated_time, result.wall_seconds,
                        result.particle_steps_per_second));
  } else if (!result.interrupted) {
    out.log("failed: " + result.error);
  }
  out.flush();
  write_summary(opt.out_dir, spec, result);
  return result;
}

// The newest checkpoint of the run that reads back whole; the ones skipped are named in notes.
template <int D>
std::optional<Checkpoint<D>> newest_valid(const std::vector<std::filesystem::path>& all,
                                          std::vector<std::string>& notes) {
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    try {
      return read_checkpoint<D>(*it);
    } catch (const CheckpointError& e) {
      notes.push_back(fmt::format("checkpoint {} cannot be used: {}; trying the one before",
                                  it->filename().string(), e.what()));
    }
  }
  return std::nullopt;
}

template <int D>
RunResult resume_dim(const RunOptions& opt, const std::vector<std::filesystem::path>& all,
                     std::vector<std::string> notes) {
  auto c = newest_valid<D>(all, notes);
  if (!c) {
    std::string why;
    for (const auto& n : notes)
      why += (why.empty() ? "" : "; ") + n;
    throw InputError(fmt::format("{}: no checkpoint can be used ({})", opt.out_dir.string(), why));
  }
  for (const auto& n : notes)
    std::cerr << "flume: " << n << "\n";
  const CaseSpec spec = read_case_string(c->case_toml, opt.out_dir / "case.toml", {});
  return run_dim<D>(spec, opt, &*c, notes);
}

}  // namespace

RunResult run_case(const CaseSpec& spec, const RunOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  return spec.dimension == 3 ? run_dim<3>(spec, options, nullptr, {})
                             : run_dim<2>(spec, options, nullptr, {});
}

RunResult resume_run(const RunOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  const auto all = list_checkpoints(options.out_dir);
  if (all.empty())
    throw InputError(
        fmt::format("{}: no checkpoint to resume from (checkpoints/ is empty or "
                    "missing: set checkpoint.every_steps or every_seconds)",
                    options.out_dir.string()));
  // The dimension from the newest file that says it (read_checkpoint checks the rest).
  std::vector<std::string> notes;
  for (auto it = all.rbegin(); it != all.rend(); ++it) {
    try {
      const int d = checkpoint_dimension(*it);
      return d == 3 ? resume_dim<3>(options, all, notes) : resume_dim<2>(options, all, notes);
    } catch (const CheckpointError&) {
      continue;  // resume_dim names it
    }
  }
  return resume_dim<2>(options, all, notes);
}

}  // namespace flume
