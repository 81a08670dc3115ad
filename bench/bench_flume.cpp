// Throughput benchmarks (Google Benchmark): neighbour search and whole steps of the dam break at
// the paper's resolution. Speed is measured here, never in the tests.
//   build/bench/flume_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <random>

#include "flume/case/build_simulation.hpp"
#include "flume/case/case_reader.hpp"
#include "flume/neighbors/cell_list.hpp"
#include "flume/validation/bundled_cases.hpp"

namespace flume {
namespace {

// Cell-list build and neighbour lists for a jittered square lattice at h = 1.3 dx (cubic spline,
// support 2h): the per-step neighbour work of a 2D run.
void BM_NeighborSearch2D(benchmark::State& state) {
  const auto side = static_cast<std::size_t>(state.range(0));
  std::vector<Vec<2>> x;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  for (std::size_t i = 0; i < side; ++i)
    for (std::size_t j = 0; j < side; ++j)
      x.push_back(
          Vec<2>{{static_cast<double>(i) + jitter(rng), static_cast<double>(j) + jitter(rng)}});
  CellList<2> cells;
  NeighborList nl;
  for (auto _ : state) {
    cells.build(x, 2.6);
    cells.find_neighbors(x, x.size(), nl);
    benchmark::DoNotOptimize(nl.index.data());
  }
  state.counters["particles/s"] =
      benchmark::Counter(static_cast<double>(x.size()) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_NeighborSearch2D)->Arg(54)->Arg(200)->Unit(benchmark::kMicrosecond)->UseRealTime();

// Whole steps of cases/dam_break.toml (2916 particles) with a given preset, from t = 0.
void BM_DamBreakStep(benchmark::State& state, const char* preset) {
  const auto spec = read_case(bundled_case("dam_break"), {std::string("scheme.preset=") + preset});
  auto sim = build_simulation<2>(spec);
  for (auto _ : state)
    sim.step(1.0);
  state.counters["particle-steps/s"] = benchmark::Counter(
      static_cast<double>(sim.particles().n_real) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_DamBreakStep, continuity, "continuity")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_DamBreakStep, standard, "standard")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace flume

BENCHMARK_MAIN();
