#include "flume/sim/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "flume/core/error.hpp"
#include "flume/integrators/time_step.hpp"

namespace flume {

template <int D>
Simulation<D>::Simulation(ParticleSet<D> particles, BoxWalls<D> walls,
                          std::unique_ptr<Scheme<D>> scheme, Physics<D> physics,
                          SimulationConfig<D> config)
    : ps_(std::move(particles)),
      walls_(std::move(walls)),
      scheme_(std::move(scheme)),
      phys_(std::move(physics)),
      config_(config) {
  check_state();
}

template <int D>
void Simulation<D>::step(double max_dt) {
  double h_max = 0.0;
  for (std::size_t i = 0; i < ps_.n_real; ++i)
    h_max = std::max(h_max, ps_.h[i]);
  const double range = scheme_->support() * h_max;

  // Re-sort real particles by cell now and then, so neighbours sit close in memory. The order
  // depends only on positions, so results stay independent of the thread count.
  std::optional<PhaseClock::Scope> phase;
  phase.emplace(&clock_, "neighbours");
  if (config_.resort_every > 0 && steps_ % config_.resort_every == 0) {
    cells_.build(std::span<const Vec<D>>(ps_.x.data(), ps_.n_real), range);
    ps_.permute(cells_.cell_order(ps_.n_real));
  }

  phase.emplace(&clock_, "boundaries");
  walls_.build_halo(ps_, range, halo_);
  halo_.append_ghosts(ps_);
  phase.emplace(&clock_, "neighbours");
  cells_.build(ps_.x, range);
  cells_.find_neighbors(ps_.x, ps_.n_real, neighbors_);
  phase.emplace(&clock_, "sweeps");
  if (config_.shepard_every > 0 && steps_ > 0 && steps_ % config_.shepard_every == 0)
    scheme_->filter_density(ps_, neighbors_, halo_);

  scheme_->compute_accelerations(ps_, neighbors_, halo_);

  const double dt_rule =
      config_.fixed_dt > 0.0 ? config_.fixed_dt : cfl_time_step(ps_, phys_, config_.cfl);
  if (steps_ == 0) first_dt_ = dt_rule;
  // A CFL step that shrinks by four orders of magnitude means particles are flying apart or
  // accelerating without bound: stop and say so instead of crawling on.
  if (!(dt_rule > 1e-4 * first_dt_) || !std::isfinite(dt_rule))
    throw SimulationError(
        fmt::format("time step collapsed to {:.3g} s (first step {:.3g} s) at "
                    "t = {:.6g} s, step {}: the simulation blew up",
                    dt_rule, first_dt_, time_, steps_));
  const double dt = std::min(dt_rule, max_dt);
  phase.emplace(&clock_, "integration");
  integrator_.kick(ps_, dt);
  if (scheme_->evolves_density()) {
    phase.emplace(&clock_, "sweeps");
    scheme_->compute_density_rate(ps_, neighbors_, halo_);
    phase.emplace(&clock_, "integration");
    integrator_.advance_density(ps_, dt);
  }
  integrator_.drift(ps_, dt);
  phase.emplace(&clock_, "boundaries");
  ps_.drop_ghosts();
  walls_.reflect_crossings(ps_, range);
  phase.emplace(&clock_, "checks");
  time_ += dt;
  last_dt_ = dt;
  ++steps_;
  check_state();
}

template <int D>
void Simulation<D>::check_state() const {
  for (std::size_t i = 0; i < ps_.n_real; ++i) {
    bool finite = std::isfinite(ps_.rho[i]);
    for (int k = 0; k < D; ++k)
      finite = finite && std::isfinite(ps_.x[i][k]) && std::isfinite(ps_.v[i][k]);
    if (!finite)
      throw SimulationError(
          fmt::format("non-finite state (NaN or infinity) of particle {} at t = {:.6g} s, step {}",
                      ps_.id[i], time_, steps_));
    if (!(ps_.rho[i] > 0.0))
      throw SimulationError(
          fmt::format("density of particle {} fell to {:.4g} kg/m^3 at t = "
                      "{:.6g} s, step {}: the simulation blew up",
                      ps_.id[i], ps_.rho[i], time_, steps_));
  }
  const long out = walls_.first_outside(ps_);
  if (out >= 0) {
    const auto i = static_cast<std::size_t>(out);
    std::string pos;
    for (int k = 0; k < D; ++k)
      pos += fmt::format("{}{:.6g}", k ? ", " : "", ps_.x[i][k]);
    throw SimulationError(
        fmt::format("particle {} lost: it left the domain at ({}) m, t = {:.6g} "
                    "s, step {}",
                    ps_.id[i], pos, time_, steps_));
  }
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace flume
