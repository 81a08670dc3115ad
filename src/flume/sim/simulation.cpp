#include "flume/sim/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include <fmt/format.h>
#include <omp.h>

#include "flume/core/error.hpp"
#include "flume/integrators/time_step.hpp"
#include "flume/sim/state_fields.hpp"

namespace flume {

template <int D>
void sort_state(ParticleSet<D>& ps, const std::vector<std::uint32_t>& order, SweepWorkspace& work) {
  const auto n = static_cast<long>(order.size());
  ps.for_each_state_field([&](auto& field) {
    using T = typename std::decay_t<decltype(field)>::value_type;
    // Resized without being cleared first (every element is overwritten below): clearing then
    // growing it would fill it with zeros, a serial memset of the whole state every step.
    auto& out = work.buffer<T>(0, order.size());
    out.reserve(field.capacity());  // the buffers trade places: both keep room for the ghosts
#pragma omp parallel for schedule(static)
    for (long k = 0; k < n; ++k)
      out[static_cast<std::size_t>(k)] = field[order[static_cast<std::size_t>(k)]];
    field.swap(out);
  });
}

template <int D>
Simulation<D>::Simulation(ParticleSet<D> particles, BoxWalls<D> walls,
                          std::unique_ptr<Scheme<D>> scheme, Physics<D> physics,
                          SimulationConfig<D> config, RepulsiveWalls<D> repulsive)
    : ps_(std::move(particles)),
      walls_(std::move(walls)),
      repulsive_(std::move(repulsive)),
      scheme_(std::move(scheme)),
      phys_(std::move(physics)),
      config_(config),
      limit_(phys_, config_.cfl, config_.step_rule) {
  ps_.drop_ghosts();
  if (config_.hydrostatic_ghosts) halo_.set_hydrostatic(phys_.gravity, phys_.eos.tait());
  ps_.use_only(scheme_->fields() | limit_.fields() | (config_.xsph > 0.0 ? kFieldXsph : 0u) |
               (config_.integrator == Integrator::leap_frog ? 0u : RungeKutta<D>::fields()));
  // The pressure of the starting density, so that the state written before the first step
  // (snapshot 0) shows it; every step recomputes it.
  for (std::size_t i = 0; i < ps_.n_real; ++i)
    ps_.p[i] = phys_.eos.pressure(ps_.rho[i], ps_.uses(kFieldEnergy) ? ps_.e[i] : 0.0);
  // The density band, from the starting densities (a gas's two sides differ by 8).
  if (ps_.n_real > 0) {
    const auto [lo, hi] = std::minmax_element(ps_.rho.begin(), ps_.rho.begin() + ps_.n_real);
    rho_lo_ = config_.density_band_lo * *lo;
    rho_hi_ = config_.density_band_hi * *hi;
  }
  walls_at(time_);
  check_state();
}

template <int D>
SimulationState Simulation<D>::state() const {
  return {time_, steps_, last_dt_, first_dt_, integrator_.history()};
}

template <int D>
void Simulation<D>::restore(const ParticleSet<D>& particles, const SimulationState& state) {
  if (particles.optional != ps_.optional)
    throw SimulationError(
        fmt::format("the saved particles carry the fields {:#x}, this case's scheme {:#x}",
                    particles.optional, ps_.optional));
  ps_.drop_ghosts();
  ps_.n_real = particles.n_real;
  ps_.resize(particles.n_real);  // every field, derived ones too, sized for the saved count
  copy_state_fields(particles, ps_, particles.n_real);
  time_ = state.time;
  steps_ = static_cast<long>(state.steps);
  last_dt_ = state.last_dt;
  first_dt_ = state.first_dt;
  integrator_.set_history(state.leapfrog_dt_prev);
  h_range_known_ = false;
  box_known_ = false;
  for (std::size_t i = 0; i < ps_.n_real; ++i)
    ps_.p[i] = phys_.eos.pressure(ps_.rho[i], ps_.uses(kFieldEnergy) ? ps_.e[i] : 0.0);
  walls_at(time_);
  check_state();
}

template <int D>
void Simulation<D>::prepare_neighbours(double range) {
  {
    PhaseClock::Scope phase(&clock_, "neighbours");
    // Sorted by cell every step: each cell, and each row of three cells, is then a contiguous
    // run of indices. The order depends only on the positions (a stable counting sort), so the
    // results do not depend on the thread count.
    const std::span<const Vec<D>> x(ps_.x.data(), ps_.n_real);
    const auto& order =
        box_known_ ? grid_.sort_real(x, range, box_.lo, box_.hi) : grid_.sort_real(x, range);
    box_known_ = false;
    sort_state(ps_, order, work_);
  }
  PhaseClock::Scope phase(&clock_, "boundaries");
  walls_.build_halo(ps_, range, halo_, grid_);
  ghost_x_.resize(halo_.size());
  for (std::size_t g = 0; g < halo_.size(); ++g)
    ghost_x_[g] = halo_.position(ps_, g);
  halo_.reorder(grid_.sort_ghosts(ghost_x_));
  halo_.append_ghosts(ps_);
}

template <int D>
double Simulation<D>::neighbours_at(double t) {
  // The smoothing lengths' range; scanned once when h does not evolve (a serial scan every
  // step cost about 1 % of the dam break's step at 1e5 particles, 2 threads).
  if (!h_range_known_ || evolved().smoothing_length) {
    h_max_ = 0.0;
    h_min_ = ps_.n_real ? ps_.h[0] : 0.0;
    for (std::size_t i = 0; i < ps_.n_real; ++i) {
      h_max_ = std::max(h_max_, ps_.h[i]);
      h_min_ = std::min(h_min_, ps_.h[i]);
    }
    h_range_known_ = true;
  }
  const double range = scheme_->support() * h_max_;
  walls_at(t);  // moving walls stand where they are at t while the rates are taken
  prepare_neighbours(range);
  uniform_h_ = h_min_ == h_max_ ? h_max_ : 0.0;
  return range;
}

template <int D>
double Simulation<D>::choose_step(double dt_stable, double max_dt) {
  const double dt_rule = config_.fixed_dt > 0.0 ? config_.fixed_dt : dt_stable;
  if (steps_ == 0) first_dt_ = dt_rule;
  // A CFL step that shrinks by four orders of magnitude means particles are flying apart or
  // accelerating without bound: stop and say so instead of crawling on.
  if (!(dt_rule > config_.min_dt_ratio * first_dt_) || !std::isfinite(dt_rule)) {
    // The particle that sets the step: the largest acceleration (the force limit of BL (63)).
    std::size_t worst = 0;
    for (std::size_t i = 1; i < ps_.n_real; ++i)
      if (!(norm(ps_.a[i]) <= norm(ps_.a[worst]))) worst = i;
    throw SimulationError(fmt::format(
        "check time_step failed at step {}, t = {:.6g} s: the step collapsed to {:.3g} s, below "
        "{:g} times the first ({:.3g} s, checks.min_dt_ratio); {} has the largest acceleration, "
        "{:.3g} m/s^2: the simulation blew up",
        steps_, time_, dt_rule, config_.min_dt_ratio, first_dt_,
        ps_.n_real ? particle_at(worst) : std::string("no particle"),
        ps_.n_real ? norm(ps_.a[worst]) : 0.0));
  }
  return std::min(dt_rule, max_dt);
}

template <int D>
double Simulation<D>::accelerations(const SweepContext<D>& ctx) {
  const double dt_stable = scheme_->compute_accelerations(ps_, ctx, halo_, limit_);
  if (repulsive_.empty()) return dt_stable;
  PhaseClock::Scope phase(&clock_, "boundaries");
  repulsive_.add_accelerations(ps_);
  // The force sweep's step saw the scheme's accelerations only: taken again with the walls'.
  return least_over_blocks(
      ps_.n_real, std::numeric_limits<double>::infinity(),
      [&](std::size_t b, std::size_t e) { return limit_.least(ps_, b, e, uniform_h_); });
}

template <int D>
void Simulation<D>::prepare_step_rule(double range) {
  if (config_.step_rule != StepRule::w388) return;
  PhaseClock::Scope phase(&clock_, "time_step");
  signal_speed_w388(grid_, ps_, range);
}

template <int D>
const std::vector<Vec<D>>* Simulation<D>::xsph_of(const SweepContext<D>& ctx,
                                                  std::vector<Vec<D>>& u) {
  if (!(config_.xsph > 0.0)) return nullptr;
  scheme_->xsph(ps_, ctx, halo_, u, config_.xsph);
  return &ps_.xsph;
}

template <int D>
int Simulation<D>::step_threads() const {
  return team_size(ps_.n_real, omp_get_max_threads(), config_.particles_per_thread);
}

template <int D>
void Simulation<D>::step(double max_dt) {
  const ThreadTeam team(step_threads());
  last_step_threads_ = omp_get_max_threads();
  switch (config_.integrator) {
    case Integrator::leap_frog:
      step_leap_frog(max_dt);
      return;
    case Integrator::runge_kutta:
      step_runge_kutta(max_dt, RungeKuttaKind::midpoint);
      return;
    case Integrator::modified_runge_kutta:
      step_runge_kutta(max_dt, RungeKuttaKind::modified);
      return;
  }
}

template <int D>
void Simulation<D>::step_leap_frog(double max_dt) {
  const double range = neighbours_at(time_);
  const SweepContext<D> ctx{grid_, work_, uniform_h_, &clock_};

  if (config_.shepard_every > 0 && steps_ > 0 && steps_ % config_.shepard_every == 0)
    scheme_->filter_density(ps_, ctx, halo_, config_.density_filter);
  prepare_step_rule(range);

  // The CFL step of the new accelerations comes out of the force sweep (time_step.hpp).
  const double dt_stable = accelerations(ctx);

  std::optional<PhaseClock::Scope> phase;
  phase.emplace(&clock_, "integration");
  const double dt = choose_step(dt_stable, max_dt);
  // The drift moves the particles to t^{n+1}; in the same pass each block is put back across
  // the walls (standing where they are at t^{n+1}) and checked (pass_with_checks): the first
  // bad particle is reported.
  walls_at(time_ + dt);
  const long none = static_cast<long>(ps_.n_real);
  const EvolvedFields state = evolved();
  const bool xsph = config_.xsph > 0.0;
  long bad = none;
  if (state.density || state.energy || state.smoothing_length || xsph) {
    // The state's rates and XSPH's drift correction take the kicked velocity v^{n+1/2}.
    integrator_.kick(ps_, dt);
    phase.reset();
    scheme_->compute_state_rates(ps_, ctx, halo_, ps_.v_half);
    const std::vector<Vec<D>>* drift = xsph_of(ctx, ps_.v_half);
    bad = pass_with_checks(range, [&](const auto& after) {
      return integrator_.advance_state_and_drift(ps_, dt, state, none, after, drift);
    });
  } else {
    phase.reset();
    bad = pass_with_checks(
        range, [&](const auto& after) { return integrator_.kick_and_drift(ps_, dt, none, after); });
  }
  finish_step(dt, bad);
}

// W (3.85)-(3.87) or W (3.92) (runge_kutta.hpp): the rates at Phi^n, a stage, the rates at
// the stage state, the end. The Shepard filter, when due, acts on Phi^n before its rates.
template <int D>
void Simulation<D>::step_runge_kutta(double max_dt, RungeKuttaKind kind) {
  const RungeKutta<D> rk(kind, evolved());
  const long none = static_cast<long>(ps_.n_real);
  double range = neighbours_at(time_);
  // The rates of the present state; with XSPH also the drift correction of its velocity (u^n,
  // the midpoint's u*, the modified step's U*), returned (else null).
  const auto rates = [&](double* stable) {
    const SweepContext<D> ctx{grid_, work_, uniform_h_, &clock_};
    if (stable && config_.shepard_every > 0 && steps_ > 0 && steps_ % config_.shepard_every == 0)
      scheme_->filter_density(ps_, ctx, halo_, config_.density_filter);
    if (stable) prepare_step_rule(range);
    const double dt_stable = accelerations(ctx);
    scheme_->compute_state_rates(ps_, ctx, halo_, ps_.v);
    if (stable) *stable = dt_stable;
    const bool stage_of_modified = !stable && kind == RungeKuttaKind::modified;
    return xsph_of(ctx, stage_of_modified ? ps_.v_half : ps_.v);
  };

  double dt_stable = 0.0;
  const std::vector<Vec<D>>* drift = rates(&dt_stable);
  std::optional<PhaseClock::Scope> phase;
  phase.emplace(&clock_, "integration");
  const double dt = choose_step(dt_stable, max_dt);
  // The stage state stands at t + dt/2 (W (3.85); W (3.92)'s Phi^{n+1/2}).
  walls_at(time_ + 0.5 * dt);
  phase.reset();
  const long bad = pass_with_checks(
      range, [&](const auto& after) { return rk.to_stage(ps_, dt, none, after, drift); });
  ps_.drop_ghosts();
  if (bad < none) {
    finish_step(0.5 * dt, bad);  // reports the particle, at the stage's time
    return;
  }
  range = neighbours_at(time_ + 0.5 * dt);
  drift = rates(nullptr);
  phase.emplace(&clock_, "integration");
  walls_at(time_ + dt);
  phase.reset();
  finish_step(dt, pass_with_checks(range, [&](const auto& after) {
                return rk.to_end(ps_, dt, none, after, drift);
              }));
}

template <int D>
void Simulation<D>::finish_step(double dt, long bad) {
  ps_.drop_ghosts();
  time_ += dt;
  last_dt_ = dt;
  ++steps_;
  if (bad < static_cast<long>(ps_.n_real)) report(static_cast<std::size_t>(bad));
}

template <int D>
std::size_t Simulation<D>::bytes() const {
  std::size_t b = 0;
  auto& ps = const_cast<ParticleSet<D>&>(ps_);
  ps.for_each_field([&b](const auto& field) {
    b += field.capacity() * sizeof(typename std::decay_t<decltype(field)>::value_type);
  });
  return b + grid_.bytes() + work_.bytes() + halo_.size() * sizeof(GhostMap<D>);
}

template <int D>
long Simulation<D>::first_unsound_of_all() const {
  // The first bad particle (lowest index), found in parallel.
  return least_over_blocks(ps_.n_real, static_cast<long>(ps_.n_real),
                           [&](std::size_t b, std::size_t e) { return first_unsound(b, e); });
}

template <int D>
long Simulation<D>::put_back_and_check(std::size_t b, std::size_t e, double range) {
  using Clock = PhaseClock::Clock;
  const auto scan = Clock::now();
  BlockExtent<D> ext = block_extent(ps_, b, e);
  double seconds = std::chrono::duration<double>(Clock::now() - scan).count();
  const bool moved = walls_.put_back(ps_, b, e, range, ext.lo, ext.hi);
  repulsive_.put_back(ps_, b, e);
  const auto start = Clock::now();
  if (moved || !repulsive_.empty()) ext = block_extent(ps_, b, e);  // particles were put back
  const long bad = first_unsound(b, e, ext);
  const auto t = static_cast<std::size_t>(omp_get_thread_num());
  join(thread_box_[t].ext, ext);
  seconds += std::chrono::duration<double>(Clock::now() - start).count();
  check_seconds_[t].s += seconds;
  return bad;
}

template <int D>
template <class Pass>
long Simulation<D>::pass_with_checks(double range, const Pass& pass) {
  const auto threads = static_cast<std::size_t>(omp_get_max_threads());
  check_seconds_.assign(threads, ThreadSeconds{});
  thread_box_.assign(threads, ThreadBox{empty_extent<D>()});
  const auto start = PhaseClock::Clock::now();
  const long bad =
      pass([&](std::size_t b, std::size_t e) { return put_back_and_check(b, e, range); });
  // Every block sound, so every position finite: the box is the union of the threads' boxes
  // (a least and a largest value are exact, in any order).
  box_known_ = bad == static_cast<long>(ps_.n_real) && ps_.n_real > 0;
  box_ = empty_extent<D>();
  for (const ThreadBox& box : thread_box_)
    join(box_, box.ext);
  const double whole = std::chrono::duration<double>(PhaseClock::Clock::now() - start).count();
  double checks = 0.0;
  for (const ThreadSeconds& t : check_seconds_)
    checks += t.s;
  checks /= static_cast<double>(check_seconds_.size());
  clock_.add("integration", whole - checks);
  clock_.add("checks", checks);
  return bad;
}

template <int D>
void Simulation<D>::check_state() const {
  const long bad = first_unsound_of_all();
  if (bad < static_cast<long>(ps_.n_real)) report(static_cast<std::size_t>(bad));
}

template <int D>
std::string Simulation<D>::particle_at(std::size_t i) const {
  std::string pos;
  for (int k = 0; k < D; ++k)
    pos += fmt::format("{}{:.6g}", k ? ", " : "", ps_.x[i][k]);
  return fmt::format("particle {} at ({}) m", ps_.id[i], pos);
}

template <int D>
void Simulation<D>::report(std::size_t i) const {
  const std::string when = fmt::format("step {}, t = {:.6g} s", steps_, time_);
  bool finite = std::isfinite(ps_.rho[i]) && (!ps_.uses(kFieldEnergy) || std::isfinite(ps_.e[i]));
  for (int k = 0; k < D; ++k)
    finite = finite && std::isfinite(ps_.x[i][k]) && std::isfinite(ps_.v[i][k]);
  if (!finite)
    throw SimulationError(
        fmt::format("check finite failed at {}: {} has a NaN or infinite state: the "
                    "simulation blew up",
                    when, particle_at(i)));
  if (!(ps_.rho[i] > rho_lo_ && ps_.rho[i] < rho_hi_)) {
    // The worst of the band's offenders: the largest factor outside it.
    std::size_t worst = i;
    double worst_factor = 0.0;
    for (std::size_t j = 0; j < ps_.n_real; ++j) {
      const double r = ps_.rho[j];
      const double factor =
          r <= 0.0 ? std::numeric_limits<double>::infinity() : std::max(rho_lo_ / r, r / rho_hi_);
      if (factor > worst_factor) {
        worst_factor = factor;
        worst = j;
      }
    }
    throw SimulationError(fmt::format(
        "check density_band failed at {}: {} has density {:.4g} kg/m^3, outside [{:.4g}, {:.4g}] "
        "(checks.density_band): the simulation blew up",
        when, particle_at(worst), ps_.rho[worst], rho_lo_, rho_hi_));
  }
  throw SimulationError(fmt::format("check inside failed at {}: {} left the domain (particle lost)",
                                    when, particle_at(i)));
}

template void sort_state<2>(ParticleSet<2>&, const std::vector<std::uint32_t>&, SweepWorkspace&);
template void sort_state<3>(ParticleSet<3>&, const std::vector<std::uint32_t>&, SweepWorkspace&);
template class Simulation<2>;
template class Simulation<3>;

}  // namespace flume
