#include "flume/case/case_checks.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "flume/case/table_reader.hpp"
#include "flume/core/error.hpp"
#include "flume/kernels/kernel.hpp"
#include "flume/schemes/registry.hpp"

namespace flume {

namespace {

// A run that cannot fit in the machine's memory is refused before anything is allocated (a
// mistyped spacing would otherwise be killed by the kernel for lack of memory, exit 137). The
// particle count is the blocks' lattice sites (an upper bound for an ellipsoid) or their random
// counts; a particle holds at least kBytesPerParticle of state and derived fields (the leanest
// preset's fields alone: flume bench reads 200-500 B per particle), and the cell grid indexes
// particles with 32-bit integers.
void check_fits_in_memory(const Reader& r, const CaseSpec& s) {
  constexpr double kBytesPerParticle = 250.0;
  double count = 0.0;
  for (const auto& fb : s.blocks) {
    if (fb.layout == "random") {
      count += static_cast<double>(fb.count);
      continue;
    }
    const double dx = fb.spacing > 0.0 ? fb.spacing : s.spacing;
    double sites = 1.0;
    for (int k = 0; k < s.dimension; ++k)
      sites *= std::floor((fb.max[k] - fb.min[k]) / dx) + 1.0;
    count += sites;
  }
  const double memory =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  const double need = count * kBytesPerParticle;
  if (count > 2.0e9 || (memory > 0.0 && need > memory))
    r.fail("particles.spacing",
           fmt::format("= {:g} m gives about {:.3g} particles, which need at least {:.3g} GB "
                       "({:g} bytes each; at most 2e9 particles); this machine has {:.3g} GB: "
                       "use a larger spacing",
                       s.spacing, count, need / 1e9, kBytesPerParticle, memory / 1e9));
}

}  // namespace

CaseSpec build_spec(const toml::table& t, const std::filesystem::path& file, int dim) {
  const std::string fname = file.string();
  Reader r(t, fname);
  CaseSpec s;
  s.file = file;
  s.dimension = dim;

  s.name = r.str("case.name");
  const auto name_char = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  };
  if (s.name.empty() || !std::all_of(s.name.begin(), s.name.end(), name_char))
    r.fail("case.name",
           fmt::format("= \"{}\": required; letters, digits, '_' and '-' only", s.name));
  s.description = r.str("case.description");
  s.end_time = r.positive("case.end_time");
  s.dt = r.non_negative("case.dt");

  s.spacing = r.positive("particles.spacing");
  s.mass = r.one_of("particles.mass", {"volume", "summation"});

  s.preset = r.one_of("scheme.preset", preset_names());
  s.kernel = r.one_of("scheme.kernel", kernel_names());
  const SchemeRows rows = *preset_rows(s.preset);
  s.density = r.str("scheme.density").empty()
                  ? rows.density
                  : r.one_of("scheme.density", {"summation", "continuity", "w350", "w379"});
  s.force = r.str("scheme.force").empty()
                ? rows.force
                : r.one_of("scheme.force", {"bl7", "bl20", "bl59", "w351", "w380"});
  s.correction = r.str("scheme.correction").empty()
                     ? rows.correction
                     : r.one_of("scheme.correction", {"none", "gradient", "shepard", "first_order",
                                                      "mixed", "renormalized"});
  const auto& combos = scheme_combinations();
  const auto has = [&](const std::string& prefix) {
    return std::any_of(combos.begin(), combos.end(),
                       [&](const std::string& c) { return c.starts_with(prefix); });
  };
  // The key to blame: the force when no correction makes a scheme of the density and force.
  if (!has(s.density + "+" + s.force + "+"))
    r.fail("scheme.force", fmt::format("= \"{}\" has no scheme with density \"{}\"; available "
                                       "density+force+correction: {}",
                                       s.force, s.density, fmt::join(combos, ", ")));
  if (!has(s.density + "+" + s.force + "+" + s.correction))
    r.fail("scheme.correction",
           fmt::format("= \"{}\" has no scheme with density \"{}\" and force \"{}\"; "
                       "available density+force+correction: {}",
                       s.correction, s.density, s.force, fmt::join(combos, ", ")));
  s.h_over_dx = r.in_range("scheme.h_over_dx", 0.5, 4.0);
  s.integrator = r.one_of("scheme.integrator", {"leapfrog", "runge_kutta", "modified_runge_kutta"});
  s.smoothing_length = r.one_of("scheme.smoothing_length", {"fixed", "evolving"});
  if (s.smoothing_length == "evolving" && s.density != "w350" && s.density != "w379")
    r.fail("scheme.smoothing_length",
           fmt::format("= \"evolving\" (W (2.22)) is for the thesis's schemes (density w350 or "
                       "w379: sph-euler, wsph, rsph), not density \"{}\"",
                       s.density));
  s.time_step = r.one_of("scheme.time_step", {"bl63", "w388"});
  // BL (59) and the gradient-corrected force carry the viscous stress 2 mu d' themselves.
  const bool corrected = s.density == "continuity" && s.correction != "none";
  s.viscous_term = r.one_of("scheme.viscous_term", {"bl24", "w511", "w57"});
  if (corrected && s.viscous_term != "bl24")
    r.fail("scheme.viscous_term",
           fmt::format("= \"{}\" is not available with correction \"{}\": the corrected force "
                       "carries the viscous stress of BL (22)-(25) (bl24)",
                       s.viscous_term, s.correction));
  s.turbulence = r.str("scheme.turbulence").empty()
                     ? rows.turbulence
                     : r.one_of("scheme.turbulence", {"none", "smagorinsky"});
  if (corrected && s.turbulence != "none")
    r.fail("scheme.turbulence",
           fmt::format("= \"{}\" is not available with correction \"{}\" (its force has no "
                       "sub-grid stress term)",
                       s.turbulence, s.correction));
  s.smagorinsky_cs = r.in_range("scheme.smagorinsky_cs", 0.0, 1.0);
  s.yoshizawa_ci = r.in_range("scheme.yoshizawa_ci", 0.0, 1.0);
  s.filter_width = r.non_negative("scheme.filter_width");
  s.xsph = r.in_range("scheme.xsph", 0.0, 1.0);
  s.cfl = r.in_range("scheme.cfl", 1e-6, 1.0);
  s.alpha = r.non_negative("scheme.alpha");
  s.beta = r.non_negative("scheme.beta");
  s.shepard_every = static_cast<int>(r.integer("scheme.shepard_every"));
  if (s.shepard_every < 0) r.fail("scheme.shepard_every", "must be >= 0 (0 = off)");
  if (s.shepard_every > 0 && s.density == "summation")
    r.fail("scheme.shepard_every",
           fmt::format("filters an evolved density; with density \"{}\" (recomputed every "
                       "step) it must be 0",
                       s.density));
  s.density_filter = r.one_of("scheme.density_filter", {"shepard", "first_order"});

  s.rho0 = r.positive("fluid.density");
  s.mu = r.non_negative("fluid.viscosity");
  s.gravity = r.vec("fluid.gravity");

  s.eos = r.one_of("eos.kind", {"tait", "ideal_gas"});
  const bool gas_scheme = s.force == "w351" || s.force == "w380";
  if (s.eos == "ideal_gas" && !gas_scheme)
    r.fail("eos.kind",
           fmt::format("= \"ideal_gas\" needs a scheme with an energy equation (sph-euler, wsph, "
                       "rsph: force w351 or w380); force \"{}\" has none",
                       s.force));
  if (s.eos == "ideal_gas" && s.turbulence != "none")
    r.fail("scheme.turbulence",
           fmt::format("= \"{}\" (LES-SPH, W 5.6) models a weakly compressible liquid: use "
                       "eos.kind = \"tait\"",
                       s.turbulence));
  s.gamma = r.in_range("eos.gamma", 1.0, 20.0);
  if (s.eos == "ideal_gas" && !(s.gamma > 1.0))
    r.fail("eos.gamma", "must exceed 1 for an ideal gas (p = (gamma - 1) rho e)");
  s.bulk_modulus = r.non_negative("eos.bulk_modulus");
  s.sound_speed = r.non_negative("eos.sound_speed");
  const double ratio = r.positive("eos.speed_ratio");
  double u_max = r.non_negative("eos.max_flow_speed");

  s.domain_min = r.vec("domain.min");
  s.domain_max = r.vec("domain.max");
  for (int k = 0; k < dim; ++k)
    if (!(s.domain_min[k] < s.domain_max[k]))
      r.fail("domain.max", fmt::format("must exceed domain.min along {}", axis_name(k)));
  for (int k = 0; k < dim; ++k)
    for (const char* side : {"_min", "_max"})
      s.walls.push_back(r.one_of(std::string("boundaries.") + axis_name(k) + side,
                                 {"free_slip", "no_slip", "open", "periodic"}));
  // W 6.1: a periodic axis is periodic on both sides (a particle leaving one re-enters at the
  // other), and a tank is periodic along x only (the vertical axis holds gravity).
  for (int k = 0; k < dim; ++k) {
    const bool lo = s.walls[2 * k] == "periodic", hi = s.walls[2 * k + 1] == "periodic";
    if (lo != hi)
      r.fail(fmt::format("boundaries.{}_{}", axis_name(k), lo ? "max" : "min"),
             fmt::format("must be \"periodic\" too: boundaries.{}_{} is periodic", axis_name(k),
                         lo ? "min" : "max"));
    if (lo && k == dim - 1)
      r.fail(fmt::format("boundaries.{}_min", axis_name(k)),
             "= \"periodic\": the vertical axis (gravity's) cannot be periodic");
  }
  s.periodic_from = r.non_negative("boundaries.periodic_from");
  s.ghost_pressure = r.one_of("boundaries.ghost_pressure", {"mirrored", "hydrostatic"});
  if (s.ghost_pressure == "hydrostatic" && s.eos != "tait")
    r.fail("boundaries.ghost_pressure",
           "= \"hydrostatic\" needs a liquid (eos.kind = \"tait\"): the step is the Tait "
           "density of p + rho g . (x_ghost - x)");
  // The summation of particles.mass sees the particles only: beside a wall it would miss the
  // ghosts' share and give the particles there masses too large.
  if (s.mass == "summation" &&
      std::any_of(s.walls.begin(), s.walls.end(), [](const std::string& w) { return w != "open"; }))
    r.fail("particles.mass",
           "= \"summation\" needs every boundary open (the sum has no wall ghosts)");

  if (const auto* moving = t.at_path("moving_walls").as_array()) {
    std::vector<std::string> sides;
    for (int k = 0; k < dim; ++k)
      for (const char* side : {"_min", "_max"})
        sides.push_back(std::string(axis_name(k)) + side);
    for (std::size_t w = 0; w < moving->size(); ++w) {
      const std::string key = fmt::format("moving_walls[{}]", w);
      MovingWall mw;
      const std::string side = r.one_of(key + ".side", sides);
      const auto idx =
          static_cast<std::size_t>(std::find(sides.begin(), sides.end(), side) - sides.begin());
      mw.axis = static_cast<int>(idx / 2);
      mw.side = static_cast<int>(idx % 2);
      if (s.walls[idx] == "open" || s.walls[idx] == "periodic")
        r.fail(key + ".side", fmt::format("= \"{}\": boundaries.{} is {}; only a wall moves", side,
                                          side, s.walls[idx]));
      for (const auto& other : s.moving_walls)
        if (other.axis == mw.axis && other.side == mw.side)
          r.fail(key + ".side", fmt::format("= \"{}\": moves in two entries", side));
      mw.velocity = r.num(key + ".velocity");
      mw.amplitude = r.num(key + ".amplitude");
      mw.period = r.non_negative(key + ".period");
      if (!std::isfinite(mw.velocity)) r.fail(key + ".velocity", "must be finite");
      if (!std::isfinite(mw.amplitude)) r.fail(key + ".amplitude", "must be finite");
      if (mw.amplitude != 0.0 && !(mw.period > 0.0))
        r.fail(key + ".period", "must be > 0 when amplitude is not 0");
      // The wall must stay clear of the opposite side over the whole run (|s(t)| is at most
      // |u| t_end + |A|): a piston that meets the far wall would squeeze the fluid to nothing.
      const double reach = std::abs(mw.velocity) * s.end_time + std::abs(mw.amplitude);
      const double width = s.domain_max[mw.axis] - s.domain_min[mw.axis];
      if (reach > width - 2.0 * s.spacing)
        r.fail(key + ".velocity",
               fmt::format("with amplitude and case.end_time the wall travels up to {:.4g} m, "
                           "which brings it within two spacings of the opposite side ({:.4g} m "
                           "away)",
                           reach, width));
      s.moving_walls.push_back(mw);
    }
  }

  const auto* blocks = t.at_path("fluid_blocks").as_array();
  if (!blocks || blocks->empty())
    r.fail("fluid_blocks", "at least one [[fluid_blocks]] is required");
  for (std::size_t b = 0; b < blocks->size(); ++b) {
    const std::string key = fmt::format("fluid_blocks[{}]", b);
    FluidBlock fb;
    fb.min = r.vec(key + ".min");
    fb.max = r.vec(key + ".max");
    fb.velocity = r.vec(key + ".velocity");
    fb.hydrostatic = r.boolean(key + ".hydrostatic");
    fb.density = r.non_negative(key + ".density");
    fb.internal_energy = r.non_negative(key + ".internal_energy");
    fb.spacing = r.non_negative(key + ".spacing");

    if (fb.density > 0.0 && fb.hydrostatic)
      r.fail(key + ".density", "is a uniform density: set hydrostatic = false with it");
    if (s.eos == "ideal_gas" && fb.hydrostatic)
      r.fail(key + ".hydrostatic", "must be false for an ideal gas (a gas block starts uniform)");
    if (s.eos == "ideal_gas" && !(fb.internal_energy > 0.0))
      r.fail(key + ".internal_energy", "must be > 0 for an ideal gas (its e, J/kg)");
    fb.velocity_gradient = r.vec(key + ".velocity_gradient");
    if (fb.velocity_gradient.size() != static_cast<std::size_t>(dim * dim))
      r.fail(
          key + ".velocity_gradient",
          fmt::format("must have {} entries (a {} x {} matrix, row-major)", dim * dim, dim, dim));
    fb.shape = r.one_of(key + ".shape", {"box", "ellipsoid"});
    fb.layout = r.one_of(key + ".layout", {"lattice", "random"});
    fb.count = r.integer(key + ".count");
    fb.seed = r.integer(key + ".seed");
    if (fb.layout == "random" && !(fb.count >= 1 && fb.count <= 100'000'000))
      r.fail(key + ".count",
             fmt::format("= {}: a random layout needs 1 to 1e8 particles", fb.count));
    if (fb.layout == "lattice" && fb.count != 0)
      r.fail(key + ".count", "is for layout = \"random\" (a lattice's count follows the spacing)");
    if (fb.seed < 0) r.fail(key + ".seed", fmt::format("= {}: must be >= 0", fb.seed));
    fb.min_distance = r.in_range(key + ".min_distance", 0.0, 1.0);
    if (fb.spacing > 0.0 && fb.layout == "random")
      r.fail(key + ".spacing", "is a lattice's spacing: not for layout = \"random\"");
    for (int k = 0; k < dim; ++k) {
      if (!(fb.min[k] < fb.max[k]))
        r.fail(key + ".max", fmt::format("must exceed min along {}", axis_name(k)));
      if (fb.min[k] < s.domain_min[k] || fb.max[k] > s.domain_max[k])
        r.fail(key, "must lie inside the domain box");
      if (fb.max[k] - fb.min[k] < s.spacing)
        r.fail(key, fmt::format("is thinner than one particle spacing along {}", axis_name(k)));
    }
    fb.surface_amplitude = r.non_negative(key + ".surface_amplitude");
    fb.surface_decay = r.non_negative(key + ".surface_decay");
    fb.surface_from = r.one_of(key + ".surface_from", {"x_min", "x_max"}) == "x_max" ? 1 : 0;
    if (fb.surface_amplitude > 0.0) {
      if (dim != 2 || fb.shape != "box" || fb.layout != "lattice")
        r.fail(key + ".surface_amplitude", "(W (6.21)'s mound) is for a 2D box on the lattice");
      if (fb.max[dim - 1] + fb.surface_amplitude > s.domain_max[dim - 1])
        r.fail(key + ".surface_amplitude", "puts the mound above the domain's top");
    }
    fb.solitary_amplitude = r.non_negative(key + ".solitary_amplitude");
    fb.solitary_centre = r.num(key + ".solitary_centre");
    fb.solitary_towards =
        r.one_of(key + ".solitary_towards", {"x_max", "x_min"}) == "x_min" ? -1 : 1;
    if (fb.solitary_amplitude > 0.0) {
      const std::string what = key + ".solitary_amplitude";
      const double depth = fb.max[dim - 1] - fb.min[dim - 1];
      if (dim != 2 || fb.shape != "box" || fb.layout != "lattice")
        r.fail(what, "(a KdV solitary wave, W (6.15)) is for a 2D box on the lattice");
      else if (fb.surface_amplitude > 0.0)
        r.fail(what, "and surface_amplitude (W (6.21)'s mound) cannot shape the same surface");
      else if (!(fb.solitary_amplitude < 0.78 * depth))
        r.fail(what, fmt::format("= {} m: must be below 0.78 H = {} m (W (6.18): a higher "
                                 "solitary wave breaks; H = max - min of the block)",
                                 fb.solitary_amplitude, 0.78 * depth));
      else if (fb.max[dim - 1] + fb.solitary_amplitude > s.domain_max[dim - 1])
        r.fail(what, "puts the crest above the domain's top");
      else if (!(gravity_magnitude(s) > 0.0))
        r.fail(what, "needs gravity (the wave's speed is sqrt(g H)(1 + A / (2 H)), W (6.16))");
      if (!(fb.solitary_centre >= fb.min[0] && fb.solitary_centre <= fb.max[0]))
        r.fail(key + ".solitary_centre",
               fmt::format("= {} m: must lie within the block along x, [{}, {}]",
                           fb.solitary_centre, fb.min[0], fb.max[0]));
    }
    fb.initial_pressure = r.one_of(key + ".initial_pressure", {"none", "velocity_field"});
    if (fb.initial_pressure == "velocity_field") {
      // case/affine_flow_pressure.hpp: an incompressible liquid ellipsoid in a straining flow
      // about its centre, v = diag(g) (x - c) with sum g = 0.
      double trace = 0.0, largest = 0.0, off = 0.0, v = 0.0;
      for (int row = 0; row < dim; ++row) {
        v = std::max(v, std::abs(fb.velocity[row]));
        for (int col = 0; col < dim; ++col) {
          const double g = fb.velocity_gradient[static_cast<std::size_t>(row * dim + col)];
          largest = std::max(largest, std::abs(g));
          if (row == col)
            trace += g;
          else
            off = std::max(off, std::abs(g));
        }
      }
      const std::string what = key + ".initial_pressure";
      if (fb.shape != "ellipsoid" || s.eos == "ideal_gas" || fb.hydrostatic || fb.density > 0.0)
        r.fail(what,
               "= \"velocity_field\" is for an ellipsoid of the liquid (eos tait) at the "
               "fluid's density (hydrostatic = false, no density)");
      if (off > 0.0 || v > 0.0 || !(std::abs(trace) <= 1e-12 * largest))
        r.fail(what,
               "= \"velocity_field\" needs a diagonal velocity_gradient with zero trace "
               "(an incompressible straining flow) and velocity = 0");
    }
    s.blocks.push_back(fb);
  }
  check_fits_in_memory(r, s);

  // Sound speed and bulk modulus: kappa = rho0 c0^2 / gamma, c0 = m u_max, u_max = sqrt(2 g H)
  // (BL (64), (66)) unless given.
  double c0 = 0.0;
  if (s.eos == "ideal_gas") {
    // A gas has no reference sound speed: each particle's own, from its p and rho.
  } else if (s.bulk_modulus > 0.0) {
    c0 = std::sqrt(s.gamma * s.bulk_modulus / s.rho0);
  } else if (s.sound_speed > 0.0) {
    c0 = s.sound_speed;
  } else {
    const double g = gravity_magnitude(s);
    if (u_max == 0.0) u_max = std::sqrt(2.0 * g * tallest_water(s));
    if (!(u_max > 0.0))
      r.fail("eos.sound_speed",
             "cannot be derived without gravity: set eos.sound_speed, "
             "eos.bulk_modulus or eos.max_flow_speed");
    c0 = ratio * u_max;
  }
  s.sound_speed = c0;
  s.bulk_modulus = s.rho0 * c0 * c0 / s.gamma;  // 0 for a gas
  read_repulsive_walls(r, t, s);

  s.output_interval = r.positive("output.interval");
  s.snapshot_interval = r.non_negative("output.snapshot_interval");
  s.profile = r.boolean("output.profile");
  {
    std::vector<std::string> axes;
    for (int k = 0; k < dim; ++k)
      axes.emplace_back(axis_name(k));
    const std::string axis = r.one_of("output.profile_axis", axes);
    s.profile_axis = static_cast<int>(std::find(axes.begin(), axes.end(), axis) - axes.begin());
  }
  s.profile_at = r.num("output.profile_at");
  s.profile_band = r.positive("output.profile_band");

  read_probes(r, s);

  s.checkpoint_every_steps = r.integer("checkpoint.every_steps");
  if (s.checkpoint_every_steps < 0)
    r.fail("checkpoint.every_steps", "must be >= 0 (0 = not by steps)");
  s.checkpoint_every_seconds = r.non_negative("checkpoint.every_seconds");
  s.checkpoint_keep = static_cast<int>(r.integer("checkpoint.keep"));
  if (s.checkpoint_keep < 1) r.fail("checkpoint.keep", "must be >= 1");
  {
    const auto band = r.numbers("checks.density_band");
    if (band.size() != 2 || !(band[0] > 0.0 && band[0] < 1.0) || !(band[1] > 1.0))
      r.fail("checks.density_band", "must be [lo, hi] with 0 < lo < 1 < hi");
    s.density_band_lo = band[0];
    s.density_band_hi = band[1];
  }
  s.min_dt_ratio = r.num("checks.min_dt_ratio");
  if (!(s.min_dt_ratio > 0.0 && s.min_dt_ratio < 1.0))
    r.fail("checks.min_dt_ratio", "must be between 0 and 1 (exclusive)");

  read_validation(r, t, file, s);
  return s;
}

toml::table spec_to_table(const CaseSpec& spec, toml::table t) {
  auto* scheme = t["scheme"].as_table();
  scheme->insert_or_assign("density", spec.density);
  scheme->insert_or_assign("force", spec.force);
  scheme->insert_or_assign("correction", spec.correction);
  scheme->insert_or_assign("turbulence", spec.turbulence);
  auto* eos = t["eos"].as_table();
  eos->insert_or_assign("bulk_modulus", spec.bulk_modulus);
  eos->insert_or_assign("sound_speed", spec.sound_speed);
  // References are found relative to the case file; the resolved file lives elsewhere (the run
  // directory), so it names them by absolute path.
  if (auto* curves = t.at_path("validation.curves").as_array()) {
    for (std::size_t c = 0; c < curves->size() && c < spec.curves.size(); ++c)
      if (spec.curves[c].theory.empty())  // "theory:NAME" is kept as written
        curves->get(c)->as_table()->insert_or_assign(
            "reference",
            std::filesystem::absolute(spec.curves[c].reference).lexically_normal().string());
  }
  return t;
}

}  // namespace flume
