// Microbenchmarks (Google Benchmark) of the pieces of a step on the dam break scaled to a given
// particle count (Wendland C2, support 2.83 dx, as `flume bench`): the neighbour preparation
// (cell sort of the real particles, mirror ghosts binned into the grid) and one sweep of each
// group the presets run. Whole steps are measured by `flume bench`.
//   build/bench/flume_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "flume/case/build_simulation.hpp"
#include "flume/case/case_reader.hpp"
#include "flume/equations/continuity_density_bl4.hpp"
#include "flume/equations/corrected_velocity_gradient.hpp"
#include "flume/equations/density_summation.hpp"
#include "flume/equations/force_bonet_lok_7.hpp"
#include "flume/equations/force_csph_bl59.hpp"
#include "flume/kernels/wendland_c2.hpp"
#include "flume/schemes/common_steps.hpp"
#include "flume/sim/simulation.hpp"
#include "flume/validation/bundled_cases.hpp"

namespace flume {
namespace {

using Kernel = WendlandC2<2>;

// The dam break of `flume bench` with about n particles, sorted by cell, ghosts appended, and
// pressure, sound speed and the CSPH fields filled so that every group can run.
struct Prepared {
  CaseSpec spec;
  Physics<2> phys;
  ParticleSet<2> ps;
  BoxWalls<2> walls;
  CellGrid<2> grid;
  Halo<2> halo;
  SweepWorkspace work;
  double range = 0.0;

  explicit Prepared(long n) {
    const double side = std::round(std::sqrt(static_cast<double>(n)));
    spec = read_case(bundled_case("dam_break"),
                     {"particles.spacing=" + std::to_string(0.05715 / side),
                      "scheme.kernel=wendland_c2", "scheme.h_over_dx=1.415", "scheme.alpha=0.02",
                      "fluid.viscosity=0", "output.snapshot_interval=0"});
    phys = build_physics<2>(spec);
    ps = build_particles<2>(spec, phys);
    ps.use_only(kFieldsAll);  // every group of every scheme runs on this set
    walls.lo = Vec<2>{{spec.domain_min[0], spec.domain_min[1]}};
    walls.hi = Vec<2>{{spec.domain_max[0], spec.domain_max[1]}};
    for (auto& axis : walls.kind)
      axis = {WallKind::free_slip, WallKind::free_slip};
    range = Kernel::support * ps.h[0];
    prepare();
    update_pressure(ps, phys, halo);
    for (std::size_t i = 0; i < ps.size(); ++i) {
      ps.shepard[i] = 1.0;
      ps.L[i] = Mat<2>::identity();
    }
  }
  void prepare() {
    ps.drop_ghosts();
    sort_state(ps, grid.sort_real(std::span<const Vec<2>>(ps.x.data(), ps.n_real), range), work);
    walls.build_halo(ps, range, halo, grid);  // as the simulation does
    std::vector<Vec<2>> gx(halo.size());
    for (std::size_t g = 0; g < halo.size(); ++g)
      gx[g] = halo.position(ps, g);
    halo.reorder(grid.sort_ghosts(gx));
    halo.append_ghosts(ps);
  }
  SweepContext<2> ctx() { return {grid, work, ps.h[0], nullptr}; }
};

void count_rate(benchmark::State& state, const Prepared& p) {
  state.counters["particles/s"] =
      benchmark::Counter(static_cast<double>(p.ps.n_real) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

void BM_NeighbourPreparation(benchmark::State& state) {
  Prepared p(state.range(0));
  for (auto _ : state)
    p.prepare();
  count_rate(state, p);
}
BENCHMARK(BM_NeighbourPreparation)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_SweepDensity(benchmark::State& state) {
  Prepared p(state.range(0));
  DensitySummation<2> density{p.ps};
  for (auto _ : state)
    sweep<2, Kernel>(p.ctx(), p.ps, "density", density);
  count_rate(state, p);
}
BENCHMARK(BM_SweepDensity)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SweepForceStandard(benchmark::State& state) {
  Prepared p(state.range(0));
  for (auto _ : state) {
    ForceBonetLok7<2> pressure{p.ps};
    accelerate<2, Kernel>(p.ctx(), p.ps, p.phys, StepLimit<2>(p.phys, 0.2), pressure);
  }
  count_rate(state, p);
}
BENCHMARK(BM_SweepForceStandard)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_SweepContinuity(benchmark::State& state) {
  Prepared p(state.range(0));
  ContinuityDensityBL4<2> continuity{p.ps, p.ps.v_half};
  for (auto _ : state)
    sweep<2, Kernel>(p.ctx(), p.ps, "continuity", continuity);
  count_rate(state, p);
}
BENCHMARK(BM_SweepContinuity)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_SweepCsphCorrection(benchmark::State& state) {
  Prepared p(state.range(0));
  CorrectedVelocityGradient<2, Correction::mixed, false> correction{p.ps};
  for (auto _ : state) {
    sweep<2, Kernel>(p.ctx(), p.ps, "correction", correction);
  }
  count_rate(state, p);
}
BENCHMARK(BM_SweepCsphCorrection)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_SweepCsphForce(benchmark::State& state) {
  Prepared p(state.range(0));
  for (auto _ : state) {
    ForceCsphBL59<2> internal{p.ps, 0.0};
    accelerate<2, Kernel>(p.ctx(), p.ps, p.phys, StepLimit<2>(p.phys, 0.2), internal);
  }
  count_rate(state, p);
}
BENCHMARK(BM_SweepCsphForce)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

// CSPH's continuity group, BL (2) with the corrected divergence of BL (55): the third sweep of
// a CSPH step (the leap-frog's rate with v^{n+1/2}).
void BM_SweepCsphContinuity(benchmark::State& state) {
  Prepared p(state.range(0));
  CorrectedContinuity<2, Correction::mixed> continuity{p.ps, p.ps.v_half};
  for (auto _ : state)
    sweep<2, Kernel>(p.ctx(), p.ps, "continuity", continuity);
  count_rate(state, p);
}
BENCHMARK(BM_SweepCsphContinuity)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace flume

BENCHMARK_MAIN();
