// One running simulation: particles, scheme, walls, integrator and neighbour search, advanced
// step by step. No I/O here: the runner decides what to write and when.
// Each step: sort by cell -> ghosts -> scheme's groups (with the CFL step) -> leap-frog, with
// the walls' put-back and the checks in the drift's pass; or, for the Runge-Kutta steps of
// W 3.4, that twice (the rates at the start and at the stage state).
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "flume/boundaries/box_walls.hpp"
#include "flume/boundaries/repulsive_walls.hpp"
#include "flume/integrators/leapfrog.hpp"
#include "flume/integrators/runge_kutta.hpp"
#include "flume/neighbors/cell_grid.hpp"
#include "flume/schemes/scheme.hpp"
#include "flume/schemes/sweep_workspace.hpp"
#include "flume/sim/block_extent.hpp"
#include "flume/sim/phase_clock.hpp"
#include "flume/sim/simulation_state.hpp"
#include "flume/sim/thread_team.hpp"

namespace flume {

// The time integration: leap-frog BL (61)-(62), or the Runge-Kutta steps of W 3.4.
enum class Integrator { leap_frog, runge_kutta, modified_runge_kutta };

template <int D>
struct SimulationConfig {
  Integrator integrator = Integrator::leap_frog;
  double cfl = 0.3;       // Courant number of BL (63)
  double fixed_dt = 0.0;  // s; 0 means the CFL rule
  int shepard_every = 0;  // steps between density filters W (6.3); 0 = never
  // The filter's average: W (6.3)'s Shepard kernel, or BL (47)-(52)'s first-order one.
  DensityFilter density_filter = DensityFilter::shepard;
  double xsph = 0.0;  // XSPH's eps, W (6.6); 0 = off
  // Mirror ghosts with the hydrostatic step in their pressure (Halo::set_hydrostatic); a
  // liquid's (Tait) only.
  bool hydrostatic_ghosts = false;
  StepRule step_rule = StepRule::bl63;  // BL (63) or W (3.88)-(3.90) (time_step.hpp)
  // The failure checks of every step: a density outside [lo, hi] times the lowest and highest
  // starting density, a step below min_dt_ratio times the first one.
  double density_band_lo = 0.0, density_band_hi = std::numeric_limits<double>::infinity();
  double min_dt_ratio = 1e-4;
  // A step runs on at most one thread per this many real particles (thread_team.hpp); 0: on
  // every thread at any size. Results are the same either way.
  std::size_t particles_per_thread = kParticlesPerThread;
};

template <int D>
class Simulation {
 public:
  // `repulsive`: walls of repulsive boundary particles inside the box (slopes, a paddle).
  Simulation(ParticleSet<D> particles, BoxWalls<D> walls, std::unique_ptr<Scheme<D>> scheme,
             Physics<D> physics, SimulationConfig<D> config, RepulsiveWalls<D> repulsive = {});

  // Advances one step, never beyond max_dt. Throws SimulationError when a check fails (a
  // non-finite value, a density outside the band, a particle leaving the domain, the step
  // collapsing); the state is then that of the failed step.
  void step(double max_dt);

  // The threads a step runs on now: OpenMP's count, at most one per
  // config.particles_per_thread real particles (thread_team.hpp).
  int step_threads() const;
  void set_particles_per_thread(std::size_t n) { config_.particles_per_thread = n; }
  // The threads the last step's parallel passes were started with (0 before the first step).
  int last_step_threads() const { return last_step_threads_; }

  // What a checkpoint holds (run/checkpoint.hpp): the clock and the integrator's memory, and
  // the particles' state fields. restore() takes them back (the particles' fields must be
  // those this simulation's scheme uses) and checks the state; the next step is then the one
  // the saved run took.
  SimulationState state() const;
  void restore(const ParticleSet<D>& particles, const SimulationState& state);

  double time() const { return time_; }
  long steps() const { return steps_; }
  double last_dt() const { return last_dt_; }
  const ParticleSet<D>& particles() const { return ps_; }
  const Physics<D>& physics() const { return phys_; }
  std::size_t ghosts() const { return halo_.size(); }
  // Seconds spent in each phase of the steps taken so far (flume bench).
  PhaseClock& phase_clock() { return clock_; }
  const PhaseClock& phase_clock() const { return clock_; }
  // Heap bytes held by the simulation's particle fields, grid and scratch (flume bench).
  std::size_t bytes() const;

 private:
  // Sorts the real particles by cell and builds the ghosts, binned into the same grid.
  void prepare_neighbours(double range);
  // The walls at time t, then prepare_neighbours for the current smoothing lengths; returns
  // the neighbour range (the kernel's support times the largest h) and sets uniform_h_.
  double neighbours_at(double t);
  // The step to take: the rule's (fixed, or the stable step of the rates) capped by max_dt.
  // Throws when the stable step has collapsed (a blow-up).
  double choose_step(double dt_stable, double max_dt);
  // The accelerations of the present state: the scheme's, then the repulsive walls' added;
  // returns the stable step of them (time_step.hpp).
  double accelerations(const SweepContext<D>& ctx);
  // Every wall, the box's and the repulsive ones, placed at time t.
  void walls_at(double t) {
    walls_.set_time(t);
    repulsive_.set_time(t);
  }
  void step_leap_frog(double max_dt);
  void step_runge_kutta(double max_dt, RungeKuttaKind kind);
  // Before the rates: the pair maximum of W (3.88), when that is the step rule.
  void prepare_step_rule(double range);
  // XSPH's correction of the velocity field u into ps.xsph (when on), or null.
  const std::vector<Vec<D>>* xsph_of(const SweepContext<D>& ctx, std::vector<Vec<D>>& u);
  // The end of every step: ghosts dropped, the clock moved on, the first unsound particle
  // (if any, bad < n_real) reported.
  void finish_step(double dt, long bad);
  EvolvedFields evolved() const {
    return {scheme_->evolves_density(), scheme_->evolves_energy(),
            scheme_->evolves_smoothing_length()};
  }
  // The first of the real particles [b, e) that is not sound (a non-finite state, a density
  // outside the band, outside the box), or n_real if none: first whether any is, in a loop
  // without branches that the compiler vectorises, then, only in a block that holds one,
  // which. (The walls' places are taken out of the loop, BoxWalls::places: read in it through
  // BoxWalls::wall, they kept the loop scalar, 2.6 % of a `standard` step at 1e5, perf.)
  long first_unsound(std::size_t b, std::size_t e) const {
    // A gas's internal energy must stay finite too (else the density is checked twice).
    const double* energy = ps_.uses(kFieldEnergy) ? ps_.e.data() : ps_.rho.data();
    Vec<D> lo, hi;
    walls_.places(lo, hi);
    const double rho_lo = rho_lo_, rho_hi = rho_hi_;
    auto sound = [&](std::size_t i) {
      const double rho = ps_.rho[i];
      bool ok = std::isfinite(rho) & (rho > rho_lo) & (rho < rho_hi) & std::isfinite(energy[i]);
      for (int k = 0; k < D; ++k)
        ok = ok & std::isfinite(ps_.x[i][k]) & std::isfinite(ps_.v[i][k]);
      return ok & BoxWalls<D>::inside(ps_.x[i], lo, hi);
    };
    int bad = 0;
#pragma omp simd reduction(| : bad)
    for (std::size_t i = b; i < e; ++i)
      bad |= sound(i) ? 0 : 1;
    if (bad)
      for (std::size_t i = b; i < e; ++i)
        if (!sound(i)) return static_cast<long>(i);
    return static_cast<long>(ps_.n_real);
  }
  // The same, knowing the block's extent (block_extent.hpp, after any put-back): the positions
  // and velocities checked through it, the density (and energy) in a loop of their own over
  // contiguous values, and only in a block that fails either, first_unsound(b, e) says which.
  long first_unsound(std::size_t b, std::size_t e, const BlockExtent<D>& ext) const {
    if (b == e) return static_cast<long>(ps_.n_real);
    Vec<D> lo, hi;
    walls_.places(lo, hi);
    // Every position inside the box: both corners of the extent are.
    if (ext.finite && BoxWalls<D>::inside(ext.lo, lo, hi) && BoxWalls<D>::inside(ext.hi, lo, hi)) {
      const double* __restrict rho = ps_.rho.data();
      const double* __restrict energy = ps_.uses(kFieldEnergy) ? ps_.e.data() : ps_.rho.data();
      const double rho_lo = rho_lo_, rho_hi = rho_hi_;
      int bad = 0;
#pragma omp simd reduction(| : bad)
      for (std::size_t i = b; i < e; ++i)
        bad |=
            std::isfinite(rho[i]) & (rho[i] > rho_lo) & (rho[i] < rho_hi) & std::isfinite(energy[i])
                ? 0
                : 1;
      if (!bad) return static_cast<long>(ps_.n_real);
    }
    return first_unsound(b, e);
  }
  // The first real particle that is not sound, or n_real.
  long first_unsound_of_all() const;
  // after(b, e) of the integrators' passes: the block's extent, the walls' put-back of the
  // particles [b, e) (the walls none of them stands beyond skipped), then their checks while
  // the block is in cache (a pass of its own read the state again: 2.5 % of a `standard` step
  // at 1e5); the first unsound one, or n_real. The time each thread spends on the extent and
  // the checks is added to check_seconds_.
  long put_back_and_check(std::size_t b, std::size_t e, double range);
  // Runs pass(after), an integrator's pass over the blocks, with after = put_back_and_check;
  // returns the first unsound particle. Timed: the checks' share (their mean time per thread)
  // is the phase "checks", the rest "integration", so `flume bench` still shows what the checks
  // cost.
  template <class Pass>
  long pass_with_checks(double range, const Pass& pass);
  struct alignas(64) ThreadSeconds {  // a cache line each: the threads do not share one
    double s = 0.0;
  };
  std::vector<ThreadSeconds> check_seconds_;
  // The real particles' bounding box as the last pass_with_checks found it (the union of its
  // blocks' extents, each thread's own, then of the threads'), for the next sort by cell, which
  // then needs no pass of its own over the positions (0.03 ms of a `standard` step at 1e5).
  // Known only from a pass that found every particle sound until the next sort takes it; a
  // restored state is not known.
  struct alignas(64) ThreadBox {  // a cache line each, as ThreadSeconds
    BlockExtent<D> ext;
  };
  std::vector<ThreadBox> thread_box_;
  BlockExtent<D> box_;
  bool box_known_ = false;
  // Throws SimulationError if a real particle is not sound (the first one, by index).
  void check_state() const;
  // Throws the SimulationError that says which check particle i failed; for the density band
  // it names the particle farthest outside it.
  [[noreturn]] void report(std::size_t i) const;
  // " particle <id> at (x, y[, z]) m"
  std::string particle_at(std::size_t i) const;

  ParticleSet<D> ps_;
  BoxWalls<D> walls_;
  RepulsiveWalls<D> repulsive_;
  std::unique_ptr<Scheme<D>> scheme_;
  Physics<D> phys_;
  SimulationConfig<D> config_;
  StepLimit<D> limit_;  // the CFL rule's per-particle limits (time_step.hpp)
  LeapFrog<D> integrator_;
  Halo<D> halo_;
  CellGrid<D> grid_;
  SweepWorkspace work_;
  std::vector<Vec<D>> ghost_x_;  // ghost positions before sorting (reused)
  double time_ = 0.0;
  double last_dt_ = 0.0;
  double first_dt_ = 0.0;   // the step rule's first value, s
  double uniform_h_ = 0.0;  // the common smoothing length of this step's particles, or 0
  // The real particles' least and largest h (neighbours_at), known until h evolves or the
  // state is restored.
  double h_min_ = 0.0, h_max_ = 0.0;
  bool h_range_known_ = false;
  long steps_ = 0;
  int last_step_threads_ = 0;
  double rho_lo_ = 0.0, rho_hi_ = 0.0;  // the density band, kg/m^3 (from the starting state)
  PhaseClock clock_;
};

// Re-orders the state fields of the real particles (ghosts dropped): new index k holds old index
// order[k]. Gathers into scratch buffers of `work` and swaps them in, so nothing is allocated once
// the buffers exist. Derived fields are not moved: every step recomputes them before use.
template <int D>
void sort_state(ParticleSet<D>& ps, const std::vector<std::uint32_t>& order, SweepWorkspace& work);

extern template class Simulation<2>;
extern template class Simulation<3>;

}  // namespace flume
