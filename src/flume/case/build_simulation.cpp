#include "flume/case/build_simulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "flume/case/affine_flow_pressure.hpp"
#include "flume/case/summation_masses.hpp"
#include "flume/core/error.hpp"
#include "flume/kernels/kernel.hpp"
#include "flume/schemes/registry.hpp"
#include "flume/theory/solitary_wave.hpp"

namespace flume {

namespace {
template <int D>
Vec<D> to_vec(const std::vector<double>& v) {
  Vec<D> out;
  for (int k = 0; k < D; ++k)
    out[k] = v[static_cast<std::size_t>(k)];
  return out;
}

WallKind wall_kind(const std::string& s) {
  if (s == "no_slip") return WallKind::no_slip;
  if (s == "open") return WallKind::open;
  if (s == "periodic") return WallKind::periodic;
  return WallKind::free_slip;
}
}  // namespace

template <int D>
Physics<D> build_physics(const CaseSpec& spec) {
  Physics<D> phys;
  phys.eos.kind = spec.eos == "ideal_gas" ? EosKind::ideal_gas : EosKind::tait;
  phys.eos.rho0 = spec.rho0;
  phys.eos.gamma = spec.gamma;
  phys.eos.kappa = spec.bulk_modulus;
  phys.mu = spec.mu;
  phys.viscous = spec.viscous_term == "w511"  ? ViscousTerm::w511
                 : spec.viscous_term == "w57" ? ViscousTerm::w57
                                              : ViscousTerm::bl24;
  phys.les.on = spec.turbulence == "smagorinsky";
  phys.les.cs = spec.smagorinsky_cs;
  phys.les.ci = spec.yoshizawa_ci;
  phys.les.delta = spec.filter_width > 0.0 ? spec.filter_width : spec.spacing;
  phys.gravity = to_vec<D>(spec.gravity);
  phys.av_alpha = spec.alpha;
  phys.av_beta = spec.beta;
  return phys;
}

namespace {

// The height of the block's free surface above x: its top, or W (6.21)'s mound on it,
// y = max_y + B exp(-k d), d the distance along x from the side the mound stands at.
template <int D>
double surface_top(const FluidBlock& block, const Vec<D>& x) {
  const double top = block.max[D - 1];
  if (block.solitary_amplitude > 0.0)
    return top + kdv_elevation(block.solitary_amplitude, top - block.min[D - 1],
                               x[0] - block.solitary_centre);
  if (!(block.surface_amplitude > 0.0)) return top;
  const double d = block.surface_from == 0 ? x[0] - block.min[0] : block.max[0] - x[0];
  return top + block.surface_amplitude * std::exp(-block.surface_decay * d);
}

// Whether x lies inside the block's shape (the box itself, below its surface, or the ellipsoid
// inscribed in it).
template <int D>
bool inside(const FluidBlock& block, const Vec<D>& x) {
  if (block.shape == "box") return x[D - 1] < surface_top<D>(block, x);
  double q = 0.0;
  for (int k = 0; k < D; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const double c = 0.5 * (block.min[kk] + block.max[kk]),
                 r = 0.5 * (block.max[kk] - block.min[kk]);
    q += (x[k] - c) * (x[k] - c) / (r * r);
  }
  return q <= 1.0;
}

// The block's volume (area in 2D): the box's, or the inscribed ellipsoid's (pi/4 of the box's
// in 2D, pi/6 in 3D).
template <int D>
double shape_volume(const FluidBlock& block) {
  double v = 1.0;
  for (int k = 0; k < D; ++k)
    v *= block.max[static_cast<std::size_t>(k)] - block.min[static_cast<std::size_t>(k)];
  if (block.shape == "box") return v;
  return v * (D == 2 ? std::numbers::pi / 4.0 : std::numbers::pi / 6.0);
}

// The positions of a block's particles: cell centres of spacing dx inside the shape (a box
// of width L holds floor(L/dx) per row; the tolerance absorbs the round-off of spacings given
// as L/n), or `count` points drawn uniformly inside it (rejection from the box).
template <int D>
std::vector<Vec<D>> block_positions(const FluidBlock& block, double dx) {
  std::vector<Vec<D>> xs;
  if (block.layout == "random") {
    std::mt19937_64 rng(static_cast<std::uint64_t>(block.seed));
    std::uniform_real_distribution<double> u(0.0, 1.0);
    xs.reserve(static_cast<std::size_t>(block.count));
    // Candidates closer than min_distance to an accepted point are drawn again (random
    // sequential addition), found through a grid of cells of that size.
    const double d = block.min_distance * dx;
    std::array<long, D> cells{};
    long n_cells = 1;
    for (int k = 0; k < D; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      cells[kk] =
          d > 0.0 ? std::max(1L, static_cast<long>((block.max[kk] - block.min[kk]) / d)) : 1L;
      n_cells *= cells[kk];
    }
    std::vector<std::vector<std::size_t>> grid(static_cast<std::size_t>(n_cells));
    const auto cell_of = [&](const Vec<D>& x, std::array<long, D>& c) {
      for (int k = 0; k < D; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        const double f = (x[k] - block.min[kk]) / (block.max[kk] - block.min[kk]);
        c[kk] =
            std::clamp(static_cast<long>(f * static_cast<double>(cells[kk])), 0L, cells[kk] - 1);
      }
    };
    const auto index = [&](const std::array<long, D>& c) {
      long i = 0;
      for (int k = D - 1; k >= 0; --k)
        i = i * cells[static_cast<std::size_t>(k)] + c[static_cast<std::size_t>(k)];
      return static_cast<std::size_t>(i);
    };
    const auto too_close = [&](const Vec<D>& x) {
      if (d <= 0.0) return false;
      std::array<long, D> c{};
      cell_of(x, c);
      long around = 1;
      for (int k = 0; k < D; ++k)
        around *= 3;
      for (long n = 0; n < around; ++n) {
        std::array<long, D> o = c;
        long rest = n;
        bool valid = true;
        for (int k = 0; k < D; ++k) {
          const auto kk = static_cast<std::size_t>(k);
          o[kk] += rest % 3 - 1;
          rest /= 3;
          valid = valid && o[kk] >= 0 && o[kk] < cells[kk];
        }
        if (!valid) continue;
        for (const std::size_t j : grid[index(o)])
          if (norm2(xs[j] - x) < d * d) return true;
      }
      return false;
    };
    long draws = 0;
    while (static_cast<long>(xs.size()) < block.count) {
      if (++draws > 10000 * block.count)
        throw InputError(
            fmt::format("fluid block: cannot place {} particles {} spacings apart (placed {})",
                        block.count, block.min_distance, xs.size()));
      Vec<D> x;
      for (int k = 0; k < D; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        x[k] = block.min[kk] + u(rng) * (block.max[kk] - block.min[kk]);
      }
      if (!inside<D>(block, x) || too_close(x)) continue;
      std::array<long, D> c{};
      cell_of(x, c);
      grid[index(c)].push_back(xs.size());
      xs.push_back(x);
    }
    // Moved as a whole so that the centre of mass (equal masses) is the shape's centre: a body
    // that starts symmetric in momentum for a velocity field odd about the centre.
    Vec<D> mean;
    for (const auto& x : xs)
      mean += x;
    mean = mean * (1.0 / static_cast<double>(xs.size()));
    for (auto& x : xs)
      for (int k = 0; k < D; ++k)
        x[k] += 0.5 * (block.min[static_cast<std::size_t>(k)] +
                       block.max[static_cast<std::size_t>(k)]) -
                mean[k];
    return xs;
  }
  std::array<long, D> count{};
  long total = 1;
  for (int k = 0; k < D; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    count[kk] = static_cast<long>(std::floor((block.max[kk] - block.min[kk]) / dx + 1e-6));
    // A mound or a solitary wave rises above the box's top: the lattice goes on by whole rows
    // past its crest, and inside() cuts it. (The rows had been counted from the crest's height
    // with the floor of the box: at 0.025 m that cut the top 2 cm off W (6.21)'s mound.)
    const double extra = k == D - 1 ? block.surface_amplitude + block.solitary_amplitude : 0.0;
    if (extra > 0.0) count[kk] += static_cast<long>(std::ceil(extra / dx));
    total *= count[kk];
  }
  for (long n = 0; n < total; ++n) {
    long rest = n;
    Vec<D> x;
    for (int k = 0; k < D; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      // A box's lattice starts dx/2 inside min (a wall there keeps its half-spacing gap); an
      // ellipsoid's is centred on it, so that a symmetric body starts symmetric (no net
      // momentum from a velocity field that is odd about the centre).
      const double first =
          block.shape == "box"
              ? block.min[kk]
              : 0.5 * (block.min[kk] + block.max[kk] - static_cast<double>(count[kk]) * dx);
      x[k] = first + (static_cast<double>(rest % count[kk]) + 0.5) * dx;
      rest /= count[kk];
    }
    if (inside<D>(block, x)) xs.push_back(x);
  }
  return xs;
}

}  // namespace

template <int D>
RepulsiveWalls<D> build_repulsive_walls(const CaseSpec& spec, const Physics<D>& phys) {
  std::vector<RepulsiveWall<D>> walls;
  for (const RepulsiveWallSpec& ws : spec.repulsive_walls) {
    RepulsiveWall<D> w;
    for (int k = 0; k < D; ++k) {
      w.from[k] = ws.from[static_cast<std::size_t>(k)];
      w.to[k] = ws.to[static_cast<std::size_t>(k)];
    }
    w.force = ws.force == "lennard_jones" ? Repulsion::lennard_jones : Repulsion::monaghan_kos;
    w.spacing = ws.spacing;
    w.lennard_jones =
        LennardJonesW67{ws.strength, ws.cutoff, ws.power_repulsive, ws.power_attractive};
    w.sound_speed = phys.eos.reference_sound_speed();
    w.put_back_distance = ws.put_back_distance;
    w.clearance = ws.clearance;
    w.reach = ws.reach;
    w.paddle =
        PistonFlapW69{ws.hinge_depth, ws.reference_height, ws.stroke, ws.frequency, ws.phase};
    walls.push_back(w);
  }
  return RepulsiveWalls<D>(std::move(walls));
}

template <int D>
ParticleSet<D> build_particles(const CaseSpec& spec, const Physics<D>& phys) {
  ParticleSet<D> ps;
  // No optional field yet: the Simulation allocates those its scheme uses (use_only). Filled
  // here, they would set the peak memory of the run (128 bytes a particle in 2D).
  ps.optional = phys.eos.is_gas() ? kFieldEnergy : 0u;  // a gas's e is state, set below
  const double dx = spec.spacing;
  const double g = norm(phys.gravity);
  std::int64_t next_id = 0;
  std::vector<std::vector<Vec<D>>> positions;
  std::size_t particles = 0;  // reserved up front: growth by doubling would inflate the peak memory
  // Repulsive walls (slopes, a paddle) cut the blocks: no particle behind one, or nearer than
  // its clearance (repulsive_walls.hpp).
  const RepulsiveWalls<D> repulsive = build_repulsive_walls<D>(spec, phys);
  for (const auto& block : spec.blocks) {
    positions.push_back(block_positions<D>(block, block.spacing > 0.0 ? block.spacing : dx));
    auto& xs = positions.back();
    std::erase_if(xs, [&](const Vec<D>& x) { return repulsive.blocked(x); });
    particles += xs.size();
  }
  ps.reserve(particles);
  for (std::size_t b = 0; b < spec.blocks.size(); ++b) {
    const FluidBlock& block = spec.blocks[b];
    // A block may have a lattice spacing of its own (equal masses across a density jump); its
    // smoothing length follows it, h = h_over_dx * spacing.
    const double block_dx = block.spacing > 0.0 ? block.spacing : dx;
    const double h = spec.h_over_dx * block_dx;
    // A lattice particle carries the volume of its cell; random ones share the shape's.
    const double volume = block.layout == "random"
                              ? shape_volume<D>(block) / static_cast<double>(block.count)
                              : std::pow(block_dx, D);
    Vec<D> centre;
    for (int k = 0; k < D; ++k)
      centre[k] =
          0.5 * (block.min[static_cast<std::size_t>(k)] + block.max[static_cast<std::size_t>(k)]);
    for (const Vec<D>& x : positions[b]) {
      Vec<D> v = to_vec<D>(block.velocity);
      for (int r = 0; r < D; ++r)
        for (int c = 0; c < D; ++c)
          v[r] += block.velocity_gradient[static_cast<std::size_t>(r * D + c)] * (x[c] - centre[c]);
      if (block.solitary_amplitude > 0.0) {  // the water under the wave, W (6.15)-(6.16)
        const double bed = block.min[D - 1];
        const KdvVelocity u = kdv_velocity(block.solitary_amplitude, block.max[D - 1] - bed, g,
                                           x[0] - block.solitary_centre, x[D - 1] - bed);
        // Toward x_min: the mirror image, both components negated (eta is even about x0).
        v[0] += block.solitary_towards * u.u;
        v[D - 1] += block.solitary_towards * u.w;
      }
      const double rho =
          block.density > 0.0 ? block.density
          : block.hydrostatic
              ? phys.eos.hydrostatic_density(g * (surface_top<D>(block, x) - x[D - 1]))
          : block.initial_pressure == "velocity_field"
              ? phys.eos.density_at_pressure(affine_flow_pressure(block, D, phys.eos.rho0, x))
              : phys.eos.rho0;
      ps.add_real(next_id++, x, v, rho * volume, rho, h);
      if (ps.uses(kFieldEnergy)) ps.e[ps.n_real - 1] = block.internal_energy;
    }
  }
  if (spec.mass == "summation") {
    const std::vector<double> masses =
        with_kernel<D>(*kernel_from_name(spec.kernel),
                       [&](auto kernel) { return summation_masses<D, decltype(kernel)>(ps); });
    std::copy(masses.begin(), masses.end(), ps.m.begin());
  }
  return ps;
}

template <int D>
Simulation<D> build_simulation(const CaseSpec& spec) {
  const Physics<D> phys = build_physics<D>(spec);
  BoxWalls<D> walls;
  walls.lo = to_vec<D>(spec.domain_min);
  walls.hi = to_vec<D>(spec.domain_max);
  for (int k = 0; k < D; ++k) {
    walls.kind[k][0] = wall_kind(spec.walls[static_cast<std::size_t>(2 * k)]);
    walls.kind[k][1] = wall_kind(spec.walls[static_cast<std::size_t>(2 * k + 1)]);
  }
  walls.periodic_from = spec.periodic_from;
  for (const auto& mw : spec.moving_walls)
    walls.motion[mw.axis][mw.side] = WallMotion{mw.velocity, mw.amplitude, mw.period};
  auto scheme =
      make_scheme<D>(SchemeRows{spec.density, spec.force, spec.correction, spec.smoothing_length},
                     *kernel_from_name(spec.kernel), phys);
  SimulationConfig<D> config;
  config.integrator = spec.integrator == "runge_kutta"            ? Integrator::runge_kutta
                      : spec.integrator == "modified_runge_kutta" ? Integrator::modified_runge_kutta
                                                                  : Integrator::leap_frog;
  config.cfl = spec.cfl;
  config.fixed_dt = spec.dt;
  config.shepard_every = spec.shepard_every;
  config.density_filter =
      spec.density_filter == "first_order" ? DensityFilter::first_order : DensityFilter::shepard;
  config.xsph = spec.xsph;
  config.hydrostatic_ghosts = spec.ghost_pressure == "hydrostatic";
  config.step_rule = spec.time_step == "w388" ? StepRule::w388 : StepRule::bl63;
  config.density_band_lo = spec.density_band_lo;
  config.density_band_hi = spec.density_band_hi;
  config.min_dt_ratio = spec.min_dt_ratio;
  return Simulation<D>(build_particles<D>(spec, phys), walls, std::move(scheme), phys, config,
                       build_repulsive_walls<D>(spec, phys));
}

template Physics<2> build_physics<2>(const CaseSpec&);
template Physics<3> build_physics<3>(const CaseSpec&);
template RepulsiveWalls<2> build_repulsive_walls<2>(const CaseSpec&, const Physics<2>&);
template RepulsiveWalls<3> build_repulsive_walls<3>(const CaseSpec&, const Physics<3>&);
template ParticleSet<2> build_particles<2>(const CaseSpec&, const Physics<2>&);
template ParticleSet<3> build_particles<3>(const CaseSpec&, const Physics<3>&);
template Simulation<2> build_simulation<2>(const CaseSpec&);
template Simulation<3> build_simulation<3>(const CaseSpec&);

}  // namespace flume
