#include "flume/validation/theory_reference.hpp"

#include <fmt/format.h>

#include <cmath>

#include "flume/case/build_simulation.hpp"
#include "flume/core/error.hpp"
#include "flume/theory/bore.hpp"
#include "flume/theory/elliptical_drop.hpp"
#include "flume/theory/solitary_wave.hpp"
#include "flume/theory/standing_wave.hpp"
#include "flume/validation/curve_compare.hpp"

namespace flume {

namespace {

io::CsvData elliptical_drop_reference(const CaseSpec& spec) {
  const FluidBlock& b = spec.blocks.front();
  const auto fail = [&](const std::string& what) {
    throw InputError(
        fmt::format("{}: validation.curves: theory:elliptical_drop: {}", spec.file.string(), what));
  };
  if (spec.dimension != 2 || b.shape != "ellipsoid") fail("needs a 2D disc as the first block");
  const double rx = 0.5 * (b.max[0] - b.min[0]), ry = 0.5 * (b.max[1] - b.min[1]);
  if (std::abs(rx - ry) > 1e-12 * ry) fail("needs a circle (equal semi-axes) at the start");
  const auto& G = b.velocity_gradient;
  if (G[1] != 0.0 || G[2] != 0.0 || G[0] != -G[3])
    fail("needs the velocity gradient diag(-A0, A0) (BL 5.2)");
  io::CsvData d;
  d.columns = {"t", "a", "b"};
  const int n = 40;
  for (int k = 1; k <= n; ++k) {
    const double t = spec.end_time * k / n;
    const auto s = elliptical_drop_exact(G[3], ry, t);
    d.rows.push_back({t, s.a, s.b});
  }
  return d;
}

// BL (67)-(68) for the first block: depth h0, speed v0 toward the x_min wall (-velocity[0]),
// gravity |g|. The front runs from the wall at v_s from t = 0; the height is h throughout.
io::CsvData bore_reference(const CaseSpec& spec) {
  const FluidBlock& b = spec.blocks.front();
  const auto fail = [&](const std::string& what) {
    throw InputError(
        fmt::format("{}: validation.curves: theory:bore: {}", spec.file.string(), what));
  };
  const auto d = static_cast<std::size_t>(spec.dimension);
  const double h0 = b.max[d - 1] - b.min[d - 1];
  const double v0 = -b.velocity[0];
  const double g = -spec.gravity[d - 1];
  if (!(v0 > 0.0)) fail("needs the first block moving toward the x_min wall (velocity[0] < 0)");
  if (!(g > 0.0)) fail("needs gravity pointing down the last axis");
  const auto sol = bore_solution(h0, v0, g);
  io::CsvData out;
  out.columns = {"t", "front", "height"};
  // At the output times, so that a window's ends are points of it.
  const auto n = static_cast<long>(std::floor(spec.end_time / spec.output_interval + 1e-9));
  for (long k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) * spec.output_interval;
    out.rows.push_back({t, sol.v_s * t, sol.h});
  }
  return out;
}

// The run's output times inside the check's window (where a window statistic is compared).
std::vector<double> window_times(const CurveCheck& check, const io::CsvData& probes) {
  const double to = check.window_to > 0.0 ? check.window_to : HUGE_VAL;
  std::vector<double> out;
  for (double t : probes.column("time"))
    if (t >= check.window_from && t <= to) out.push_back(t);
  return out;
}

// Still water W 6.5 for the still depth H: a bed pressure of rho0 g H, the level at H; at the
// run's own output times (its last time is the end time to round-off, which a grid of
// multiples of the interval could miss by an ulp and so leave a window uncovered).
io::CsvData still_water_reference(const CaseSpec& spec, const io::CsvData& probes) {
  const double g = gravity_magnitude(spec), h = spec.still_depth;
  io::CsvData out;
  out.columns = {"t", "bed_pressure", "water_level", "zero"};
  for (double t : probes.column("time"))
    out.rows.push_back({t, spec.rho0 * g * h, h, 0.0});
  return out;
}

// KdV W (6.16) for the run's own crest: the amplitude its measured speed implies (constant),
// the crest track at the speed its measured amplitude implies (a line through the window's
// first point, so that its slope is that speed), the width W (6.17) of its measured amplitude
// (for crest_width) and zero (for crest_shape, an absolute deviation).
io::CsvData kdv_reference(const CaseSpec& spec, const CurveCheck& check,
                          const io::CsvData& probes) {
  const double g = gravity_magnitude(spec), h = spec.still_depth;
  const double to = check.window_to > 0.0 ? check.window_to : HUGE_VAL;
  const auto t = probes.column("time");
  const double speed =
      window_statistic(t, probes.column("crest_x"), CurveStatistic::slope, check.window_from, to);
  const double amplitude = window_statistic(t, probes.column("crest_amplitude"),
                                            CurveStatistic::mean, check.window_from, to);
  io::CsvData out;
  out.columns = {"t", "amplitude", "crest_x", "width", "zero"};
  const double v = kdv_speed(amplitude, h, g);
  const double width = amplitude > 0.0 ? kdv_width(amplitude, h) : 0.0;
  for (double tw : window_times(check, probes))
    out.rows.push_back({tw, kdv_amplitude(speed, h, g), v * tw, width, 0.0});
  return out;
}

// The mass of the case's fluid particles as they are laid out (per unit width in 2D), or with
// `volume` their volume, sum m / rho (a lattice spacing's square or cube each).
double fluid_mass(const CaseSpec& s, bool volume = false) {
  double m = 0.0;
  auto sum = [&](const auto& ps) {
    for (std::size_t i = 0; i < ps.n_real; ++i)
      m += volume ? ps.m[i] / ps.rho[i] : ps.m[i];
  };
  if (s.dimension == 3)
    sum(build_particles<3>(s, build_physics<3>(s)));
  else
    sum(build_particles<2>(s, build_physics<2>(s)));
  return m;
}

// The water's centre of mass while its last fluid block falls freely and the rest is at rest:
// y(t) = y(0) - f g t^2 / 2, f the block's share of the mass, from the particles as the case
// lays them out (a lattice disc holds a little more or less water than the circle), from the
// run's first reading, at the run's output times.
io::CsvData free_fall_reference(const CaseSpec& spec, const io::CsvData& probes) {
  CaseSpec last = spec;
  last.blocks = {spec.blocks.back()};
  const double f = fluid_mass(last) / fluid_mass(spec), g = gravity_magnitude(spec);
  const auto t = probes.column("time"), y = probes.column("centre_y");
  io::CsvData out;
  out.columns = {"t", "centre_y"};
  for (std::size_t k = 0; k < t.size(); ++k)
    out.rows.push_back({t[k], y.front() - 0.5 * f * g * t[k] * t[k]});
  return out;
}

// The first sloshing mode of a closed 2D tank (theory/standing_wave.hpp): T_1 for the tank's
// length L (between the x walls: the domain) and the still depth H of the water as laid out,
// its volume / L: a case that starts with a mound (W (6.21)) sloshes about a level above the
// block's top. At the run's output times in the window.
io::CsvData standing_wave_reference(const CaseSpec& spec, const CurveCheck& check,
                                    const io::CsvData& probes) {
  const auto fail = [&](const std::string& what) {
    throw InputError(
        fmt::format("{}: validation.curves: theory:standing_wave: {}", spec.file.string(), what));
  };
  if (spec.dimension != 2) fail("needs a 2D tank");
  const auto mirror = [](const std::string& w) { return w == "free_slip" || w == "no_slip"; };
  if (!mirror(spec.walls[0]) || !mirror(spec.walls[1]) || !spec.moving_walls.empty() ||
      !spec.repulsive_walls.empty())
    fail("needs a closed tank: fixed ghost walls at x_min and x_max, no other walls");
  const double length = spec.domain_max[0] - spec.domain_min[0];
  const double depth = fluid_mass(spec, true) / length;
  const double period = standing_wave_period(1, length, depth, gravity_magnitude(spec));
  io::CsvData out;
  out.columns = {"t", "period"};
  for (double tw : window_times(check, probes))
    out.rows.push_back({tw, period});
  return out;
}

// The probe's own statistic over the reference window, as a table over the check's window
// whose statistic is that value (a constant for a mean, a line of that slope for a slope; for
// line_at the reference window's line itself, extrapolated: its value at `at` is the place the
// earlier track predicts, so the error is the phase shift).
io::CsvData self_reference(const CurveCheck& check, const io::CsvData& probes) {
  const auto t = probes.column("time"), y = probes.column(check.probe);
  const double value =
      window_statistic(t, y, check.statistic, check.reference_from, check.reference_to);
  io::CsvData out;
  out.columns = {"t", "value"};
  for (double tw : window_times(check, probes)) {
    const double v = check.statistic == CurveStatistic::slope ? value * tw
                     : check.statistic == CurveStatistic::line_at
                         ? window_statistic(t, y, CurveStatistic::line_at, check.reference_from,
                                            check.reference_to, tw)
                         : value;
    out.rows.push_back({tw, v});
  }
  return out;
}

// The companion run's column reference_probe at its own output times (its whole run: the
// comparison takes the check's window). No companion (its run did not complete): no rows, so
// the check has no points.
io::CsvData companion_reference(const CurveCheck& check, const io::CsvData* companion) {
  io::CsvData out;
  out.columns = {"t", "value"};
  if (companion == nullptr) return out;
  const auto t = companion->column("time"), y = companion->column(check.reference_probe);
  for (std::size_t k = 0; k < t.size(); ++k)
    out.rows.push_back({t[k], y[k]});
  return out;
}

}  // namespace

io::CsvData curve_reference(const CaseSpec& spec, const CurveCheck& check,
                            const io::CsvData& probes, const io::CsvData* companion) {
  if (check.theory == "run") return companion_reference(check, companion);
  if (check.theory.empty()) return io::read_csv(check.reference);
  if (check.theory == "elliptical_drop") return elliptical_drop_reference(spec);
  if (check.theory == "bore") return bore_reference(spec);
  if (check.theory == "still_water") return still_water_reference(spec, probes);
  if (check.theory == "kdv") return kdv_reference(spec, check, probes);
  if (check.theory == "self") return self_reference(check, probes);
  if (check.theory == "free_fall") return free_fall_reference(spec, probes);
  if (check.theory == "standing_wave") return standing_wave_reference(spec, check, probes);
  throw InputError(
      fmt::format("{}: unknown reference theory:{}", spec.file.string(), check.theory));
}

}  // namespace flume
