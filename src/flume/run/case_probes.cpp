#include "flume/run/case_probes.hpp"

#include <cmath>
#include <limits>

#include "flume/probes/bore.hpp"
#include "flume/probes/column_height.hpp"
#include "flume/probes/crest_profile.hpp"
#include "flume/probes/fluid_body.hpp"
#include "flume/probes/surge_front.hpp"
#include "flume/probes/water_depth.hpp"

namespace flume {

template <int D>
CaseProbes<D>::CaseProbes(const CaseSpec& spec) : spec_(spec) {
  if (spec.semi_axes) {
    // Nominal semi-axes from the first fluid block.
    const auto& b = spec.blocks.front();
    semi_axes_.emplace(
        std::array<double, 2>{0.5 * (b.max[0] - b.min[0]), 0.5 * (b.max[1] - b.min[1])});
  }
  if (spec.waves) waves_.emplace(spec.still_depth, spec.gauges, spec.second_crest);
  if (spec.breaking) breaking_.emplace(spec.spacing, spec.breaking_threshold);
  if (spec.beach_slope > 0.0) shoaling_.emplace(spec.still_depth, spec.beach_slope, spec.beach_toe);
  // The beaches: the fixed repulsive walls that face up (a paddle moves and stands upright).
  std::vector<std::array<double, 4>> beaches;
  for (const auto& w : spec.repulsive_walls) {
    const bool faces_up = w.to[0] > w.from[0];  // the fluid on the left walking along +x: above
    if (w.stroke == 0.0 && faces_up) beaches.push_back({w.from[0], w.from[1], w.to[0], w.to[1]});
  }
  if (!beaches.empty() && spec.waves)
    bed_ = bed_heights(beaches, spec.domain_min[0], spec.domain_max[0], spec.spacing,
                       spec.domain_min[1]);
}

template <int D>
std::vector<std::string> CaseProbes<D>::columns() const {
  std::vector<std::string> cols{"time"};
  if (spec_.semi_axes) cols.insert(cols.end(), {"semi_axis_x", "semi_axis_y"});
  if (spec_.surge_front) cols.push_back("surge_front");
  if (spec_.column_height) cols.push_back("column_height");
  if (spec_.bore) cols.insert(cols.end(), {"bore_front", "bore_height"});
  if (spec_.waves) {
    cols.insert(cols.end(), {"crest_x", "crest_amplitude", "crest_centre_x"});
    if (spec_.crest_profile)
      cols.insert(cols.end(), {"crest_width", "crest_shape", "crest_fit_amplitude"});
    if (spec_.second_crest > 0.0) cols.insert(cols.end(), {"crest2_x", "crest2_amplitude"});
    if (spec_.second_crest > 0.0 && spec_.crest_profile) cols.push_back("crest2_fit_amplitude");
    for (std::size_t g = 0; g < spec_.gauges.size(); ++g)
      cols.push_back("gauge_" + std::to_string(g + 1));
    if (spec_.beach_slope > 0.0)
      cols.insert(cols.end(), {"incident_amplitude", "grilli_s0", "grilli_breaks"});
  }
  if (spec_.breaking) cols.insert(cols.end(), {"overturn", "broken_at", "broken_x"});
  if (spec_.still_water) cols.insert(cols.end(), {"bed_pressure", "water_level"});
  if (spec_.density_deviation) cols.push_back("density_deviation");
  if (spec_.centre_of_mass) {
    cols.insert(cols.end(), {"centre_x", "centre_y"});
    if (D == 3) cols.push_back("centre_z");
  }
  return cols;
}

template <int D>
std::vector<double> CaseProbes<D>::row(const Simulation<D>& sim) {
  const auto& ps = sim.particles();
  const double wall = spec_.domain_min[0];
  const double floor = spec_.domain_min[D - 1];
  std::vector<double> row{sim.time()};
  std::array<double, 3> breaking_row{};
  if constexpr (D == 2) {
    if (semi_axes_) {
      const auto ab = (*semi_axes_)(ps);
      row.insert(row.end(), ab.begin(), ab.end());
    }
  }
  if (spec_.surge_front || spec_.column_height || spec_.bore || spec_.breaking) {
    const auto body = main_fluid_body(ps, spec_.detach_gap * spec_.spacing);
    if (spec_.surge_front)
      row.push_back(
          surge_front(ps, body, wall, floor, spec_.floor_layer * spec_.spacing, spec_.spacing));
    if (spec_.column_height)
      row.push_back(
          column_height(ps, body, wall, floor, spec_.wall_band * spec_.spacing, spec_.spacing));
    if constexpr (D == 2) {
      if (spec_.bore) {
        // h0: the depth of the incoming layer, the first fluid block's height.
        const auto& b = spec_.blocks.front();
        const auto m = measure_bore(ps, body, wall, spec_.rho0, b.max[1] - b.min[1], spec_.spacing);
        row.insert(row.end(), {m.front, m.height});
      }
    }
    if constexpr (D == 2) {
      // In the order of columns(): after the waves' columns.
      if (breaking_) breaking_row = (*breaking_)(ps, body, wall, sim.time());
    }
  }
  if constexpr (D == 2) {
    if (waves_) {
      // Every particle counts: a wave tank's spray is water the depth must hold.
      const bool periodic = spec_.walls[0] == "periodic" && sim.time() >= spec_.periodic_from;
      const auto depth =
          depth_profile(ps, nullptr, spec_.domain_min[0], spec_.domain_max[0], spec_.rho0,
                        spec_.spacing, periodic, bed_.empty() ? nullptr : &bed_);
      const auto w = (*waves_)(depth);
      row.insert(row.end(), {w.crest_x, w.crest_amplitude, w.crest_centre_x});
      if (spec_.crest_profile) {
        const auto c = crest_profile(depth, spec_.still_depth, w.crest_x, w.crest_amplitude);
        row.insert(row.end(), {c.width, c.shape, c.fit_amplitude});
      }
      if (spec_.second_crest > 0.0) row.insert(row.end(), {w.crest2_x, w.crest2_amplitude});
      if (spec_.second_crest > 0.0 && spec_.crest_profile) {
        // No second crest (NaN place): no fit either.
        const bool found = std::isfinite(w.crest2_x);
        row.push_back(found
                          ? crest_profile(depth, spec_.still_depth, w.crest2_x, w.crest2_amplitude)
                                .fit_amplitude
                          : std::numeric_limits<double>::quiet_NaN());
      }
      row.insert(row.end(), w.gauges.begin(), w.gauges.end());
      if (shoaling_) {
        const auto g = (*shoaling_)(w.crest_x, w.crest_amplitude);
        row.insert(row.end(), g.begin(), g.end());
      }
    }
    if (breaking_) row.insert(row.end(), breaking_row.begin(), breaking_row.end());
  }
  if (spec_.still_water || spec_.density_deviation) {
    // The middle 80 % of the tank, or the span the case names.
    const double lo = spec_.domain_min[0], hi = spec_.domain_max[0], margin = 0.1 * (hi - lo);
    const bool span = spec_.bed_span.size() == 2;
    const auto s = read_still_water(ps, span ? spec_.bed_span[0] : lo + margin,
                                    span ? spec_.bed_span[1] : hi - margin, floor, spec_.rho0,
                                    gravity_magnitude(spec_), spec_.spacing);
    if (spec_.still_water) row.insert(row.end(), {s.bed_pressure, s.water_level});
    if (spec_.density_deviation) row.push_back(s.density_deviation);
  }
  if (spec_.centre_of_mass) {
    // Mass-weighted, in index order (the particles' order depends on the positions only).
    Vec<D> mx{};
    double mass = 0.0;
    for (std::size_t i = 0; i < ps.n_real; ++i) {
      mx += ps.x[i] * ps.m[i];
      mass += ps.m[i];
    }
    for (int k = 0; k < D; ++k)
      row.push_back(mass > 0.0 ? mx[k] / mass : 0.0);
  }
  return row;
}

template <int D>
std::vector<double> CaseProbes<D>::state() const {
  std::vector<double> out;
  for (const auto& part : {semi_axes_ ? semi_axes_->state() : std::vector<double>{},
                           waves_ ? waves_->state() : std::vector<double>{},
                           breaking_ ? breaking_->state() : std::vector<double>{},
                           shoaling_ ? shoaling_->state() : std::vector<double>{}}) {
    out.push_back(static_cast<double>(part.size()));
    out.insert(out.end(), part.begin(), part.end());
  }
  return out;
}

template <int D>
void CaseProbes<D>::restore(const std::vector<double>& s) {
  std::size_t at = 0;
  const auto next = [&] {
    std::vector<double> part;
    if (at >= s.size()) return part;
    const auto n = static_cast<std::size_t>(s[at++]);
    for (std::size_t k = 0; k < n && at < s.size(); ++k)
      part.push_back(s[at++]);
    return part;
  };
  const auto semi = next();
  const auto wave = next();
  const auto broken = next();
  const auto shoaled = next();
  if (semi_axes_) semi_axes_->restore(semi);
  if (waves_) waves_->restore(wave);
  if (breaking_) breaking_->restore(broken);
  if (shoaling_) shoaling_->restore(shoaled);
}

template class CaseProbes<2>;
template class CaseProbes<3>;

}  // namespace flume
