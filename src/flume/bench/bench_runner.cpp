#include "flume/bench/bench_runner.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <span>

#include "flume/bench/neighbour_count.hpp"
#include "flume/case/build_simulation.hpp"
#include "flume/run/child_process.hpp"
#include "flume/sim/diagnostics.hpp"

namespace flume {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

template <int D>
BenchResult run_dim(const BenchConfig& config, const CaseSpec& spec) {
  BenchResult r;
  r.preset = config.preset;
  r.requested_particles = config.particles;
  r.spacing = spec.spacing;
  r.support = config.support;
  r.warmup = config.warmup;
  r.steps = config.steps;
  r.threads = omp_get_max_threads();

  const auto setup_start = Clock::now();
  Simulation<D> sim = build_simulation<D>(spec);
  // Every thread asked, at any size: a benchmark measures the thread count it names.
  sim.set_particles_per_thread(0);
  r.setup_seconds = seconds_since(setup_start);
  r.particles = sim.particles().n_real;

  // Warm-up: first-touch page faults, the first re-sort and the growth of the neighbour and
  // ghost arrays happen here, not in the timed steps.
  for (int s = 0; s < config.warmup; ++s)
    sim.step(1.0);
  sim.phase_clock().reset();

  // Output: what a real run computes at each output interval (runner.cpp: the first step at or
  // past each multiple of output.interval). Only the diagnostics row is computed, none written.
  const double interval = spec.output_interval;
  const double eps = 1e-12 * interval;
  long next_output = static_cast<long>(std::floor(sim.time() / interval + 1e-9)) + 1;
  std::vector<double> row;

  struct Repeat {
    double wall = 0.0;
    std::vector<std::pair<std::string, double>> phases;
  };
  std::vector<Repeat> repeats;
  for (int k = 0; k < config.repeats; ++k) {
    sim.phase_clock().reset();
    double output_seconds = 0.0;
    const auto start = Clock::now();
    for (int s = 0; s < config.steps; ++s) {
      sim.step(1.0);  // max_dt 1 s never binds: one CFL step
      if (sim.time() >= static_cast<double>(next_output) * interval - eps) {
        const auto out_start = Clock::now();
        row =
            diagnostics_row(sim.particles(), sim.physics(), sim.time(), sim.steps(), sim.last_dt());
        output_seconds += seconds_since(out_start);
        while (static_cast<double>(next_output) * interval <= sim.time() + eps)
          ++next_output;
      }
    }
    Repeat rep;
    rep.wall = seconds_since(start);
    rep.phases = sim.phase_clock().totals();
    rep.phases.emplace_back("output", output_seconds);
    r.repeat_seconds.push_back(rep.wall);
    repeats.push_back(std::move(rep));
  }
  // The median repeat (the upper one of an even count), with its own phases.
  std::vector<std::size_t> order(repeats.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return repeats[a].wall < repeats[b].wall; });
  const Repeat& median = repeats[order[order.size() / 2]];
  r.wall_seconds = median.wall;
  r.phases = median.phases;

  // Every flume kernel the bench uses (Wendland C2) reaches 2h.
  const auto& ps = sim.particles();
  r.neighbours = mean_neighbour_count<D>(std::span<const Vec<D>>(ps.x.data(), ps.n_real),
                                         2.0 * spec.h_over_dx * spec.spacing);
  r.particle_steps_per_second =
      r.wall_seconds > 0.0
          ? static_cast<double>(r.particles) * static_cast<double>(r.steps) / r.wall_seconds
          : 0.0;
  r.interactions_per_second = r.particle_steps_per_second * r.neighbours;
  return r;
}

}  // namespace

BenchResult run_bench(const BenchConfig& config, const CaseSpec& spec) {
  if (config.threads > 0) omp_set_num_threads(config.threads);
  return spec.dimension == 3 ? run_dim<3>(config, spec) : run_dim<2>(config, spec);
}

BenchResult run_bench_isolated(const BenchConfig& config, const CaseSpec& spec) {
  const ChildResult child =
      run_in_child([&] { return bench_result_json(run_bench(config, spec)).dump(); });
  BenchResult r;
  if (child.exited && child.exit_code == 0) {
    try {
      r = bench_result_from_json(nlohmann::ordered_json::parse(child.output));
    } catch (const nlohmann::json::exception& e) {
      r.error = fmt::format("unreadable result from the benchmark process: {}", e.what());
    }
  } else if (child.exited && !child.output.empty()) {
    r.error = child.output;
  } else {
    r.error = how_it_ended(child);
  }
  if (!r.error.empty()) {
    r.preset = config.preset;
    r.requested_particles = config.particles;
    r.support = config.support;
  }
  r.peak_rss_bytes = child.peak_rss_bytes;
  r.bytes_per_particle =
      r.particles > 0 ? static_cast<double>(r.peak_rss_bytes) / static_cast<double>(r.particles)
                      : 0.0;
  return r;
}

nlohmann::ordered_json bench_result_json(const BenchResult& r) {
  nlohmann::ordered_json j;
  // The keys of the speed issue first, then what makes the run repeatable.
  j["preset"] = r.preset;
  j["particles"] = r.particles;
  j["neighbours"] = r.neighbours;
  j["steps"] = r.steps;
  j["wall_seconds"] = r.wall_seconds;
  j["particle_steps_per_second"] = r.particle_steps_per_second;
  j["interactions_per_second"] = r.interactions_per_second;
  j["bytes_per_particle"] = r.bytes_per_particle;
  j["threads"] = r.threads;
  nlohmann::ordered_json phases = nlohmann::ordered_json::object();
  for (const auto& [name, seconds] : r.phases)
    phases[name] = seconds;
  j["phases"] = phases;
  j["requested_particles"] = r.requested_particles;
  j["spacing"] = r.spacing;
  j["support_in_spacings"] = r.support;
  j["warmup_steps"] = r.warmup;
  j["repeat_wall_seconds"] = r.repeat_seconds;
  j["setup_seconds"] = r.setup_seconds;
  j["peak_rss_bytes"] = r.peak_rss_bytes;
  return j;
}

BenchResult bench_result_from_json(const nlohmann::ordered_json& j) {
  BenchResult r;
  r.preset = j.at("preset").get<std::string>();
  r.particles = j.at("particles").get<std::size_t>();
  r.neighbours = j.at("neighbours").get<double>();
  r.steps = j.at("steps").get<long>();
  r.wall_seconds = j.at("wall_seconds").get<double>();
  r.particle_steps_per_second = j.at("particle_steps_per_second").get<double>();
  r.interactions_per_second = j.at("interactions_per_second").get<double>();
  r.bytes_per_particle = j.at("bytes_per_particle").get<double>();
  r.threads = j.at("threads").get<int>();
  for (const auto& [name, seconds] : j.at("phases").items())
    r.phases.emplace_back(name, seconds.get<double>());
  r.requested_particles = j.at("requested_particles").get<double>();
  r.spacing = j.at("spacing").get<double>();
  r.support = j.at("support_in_spacings").get<double>();
  r.warmup = j.at("warmup_steps").get<long>();
  r.repeat_seconds = j.at("repeat_wall_seconds").get<std::vector<double>>();
  r.setup_seconds = j.at("setup_seconds").get<double>();
  r.peak_rss_bytes = j.at("peak_rss_bytes").get<long>();
  return r;
}

}  // namespace flume
