// The readers of the case file's [probes] and [validation] sections (table_reader.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "flume/case/table_reader.hpp"
#include "flume/sim/diagnostics_columns.hpp"
#include "flume/validation/variant.hpp"

namespace flume {

namespace {

// The probes.csv columns a curve may compare (those the case's [probes] measure are checked
// separately, with a message naming the probe).
std::vector<std::string> probe_names(const CaseSpec& s) {
  std::vector<std::string> names{
      "surge_front",   "column_height",    "semi_axis_x",       "semi_axis_y",
      "bore_front",    "bore_height",      "crest_x",           "crest_amplitude",
      "bed_pressure",  "water_level",      "density_deviation", "centre_x",
      "centre_y",      "centre_z",         "overturn",          "broken_at",
      "crest2_x",      "crest2_amplitude", "broken_x",          "incident_amplitude",
      "grilli_s0",     "grilli_breaks",    "crest_width",       "crest_shape",
      "crest_centre_x"};
  names.insert(names.end(), {"crest_fit_amplitude", "crest2_fit_amplitude"});
  for (std::size_t g = 0; g < s.gauges.size(); ++g)
    names.push_back(fmt::format("gauge_{}", g + 1));
  return names;
}

}  // namespace

void read_probes(const Reader& r, CaseSpec& s) {
  s.surge_front = r.boolean("probes.surge_front");
  s.column_height = r.boolean("probes.column_height");
  // A probe of a 2D tank (x along it, y up), refused in 3D.
  const auto flag_2d = [&](const std::string& key) {
    const bool on = r.boolean(key);
    if (on && s.dimension != 2) r.fail(key, "is for 2D cases");
    return on;
  };
  s.semi_axes = flag_2d("probes.semi_axes");
  s.bore = flag_2d("probes.bore");
  s.floor_layer = r.positive("probes.floor_layer");
  s.wall_band = r.positive("probes.wall_band");
  s.detach_gap = r.positive("probes.detach_gap");

  s.waves = flag_2d("probes.waves");
  s.gauges = r.numbers("probes.gauges");
  if (!s.gauges.empty() && !s.waves) r.fail("probes.gauges", "needs probes.waves = true");
  for (double xg : s.gauges)
    if (!(xg >= s.domain_min[0] && xg <= s.domain_max[0]))
      r.fail("probes.gauges", fmt::format("{} m: outside the domain along x", xg));
  s.second_crest = r.non_negative("probes.second_crest");
  if (s.second_crest > 0.0 && !s.waves) r.fail("probes.second_crest", "needs probes.waves = true");
  s.crest_profile = r.boolean("probes.crest_profile");
  if (s.crest_profile && !s.waves) r.fail("probes.crest_profile", "needs probes.waves = true");
  s.still_depth = r.non_negative("probes.still_depth");
  if (s.still_depth == 0.0) {
    const auto& b = s.blocks.front();
    const auto d = static_cast<std::size_t>(s.dimension);
    s.still_depth = b.max[d - 1] - s.domain_min[d - 1];
  }
  s.still_water = r.boolean("probes.still_water");
  s.density_deviation = r.boolean("probes.density_deviation");
  s.centre_of_mass = r.boolean("probes.centre_of_mass");
  s.breaking = flag_2d("probes.breaking");
  s.breaking_threshold = r.positive("probes.breaking_threshold");
  s.bed_span = r.numbers("probes.bed_span");
  if (!s.bed_span.empty() && (s.bed_span.size() != 2 || !(s.bed_span[0] < s.bed_span[1]) ||
                              s.bed_span[0] < s.domain_min[0] || s.bed_span[1] > s.domain_max[0]))
    r.fail("probes.bed_span", "must be [x_lo, x_hi] with x_lo < x_hi inside the domain along x");
  s.beach_slope = r.non_negative("probes.beach_slope");
  s.beach_toe = r.num("probes.beach_toe");
  if (s.beach_slope > 0.0 && !s.waves) r.fail("probes.beach_slope", "needs probes.waves = true");
  if (s.beach_slope > 0.0 && !(s.beach_toe > s.domain_min[0] && s.beach_toe < s.domain_max[0]))
    r.fail("probes.beach_toe", "must lie inside the domain along x");
}

void read_repulsive_walls(const Reader& r, const toml::table& t, CaseSpec& s) {
  const auto* walls = t.at_path("repulsive_walls").as_array();
  if (!walls) return;
  const int dim = s.dimension;
  for (std::size_t w = 0; w < walls->size(); ++w) {
    const std::string key = fmt::format("repulsive_walls[{}]", w);
    if (dim != 2) r.fail(key, "repulsive walls are for 2D cases");
    if (s.eos != "tait")
      r.fail(key, "needs eos.kind = \"tait\" (the wall's push scales with its sound speed)");
    RepulsiveWallSpec ws;
    ws.from = r.vec(key + ".from");
    ws.to = r.vec(key + ".to");
    const double length = std::hypot(ws.to[0] - ws.from[0], ws.to[1] - ws.from[1]);
    if (!(length > 0.0)) r.fail(key + ".to", "must differ from `from` (a wall has a length)");
    for (const auto* end : {&ws.from, &ws.to})
      for (int k = 0; k < dim; ++k)
        if (!((*end)[k] >= s.domain_min[k] && (*end)[k] <= s.domain_max[k]))
          r.fail(key + (end == &ws.from ? ".from" : ".to"), "must lie inside the domain box");
    ws.force = r.one_of(key + ".force", {"monaghan_kos", "lennard_jones"});
    ws.spacing = r.non_negative(key + ".spacing");
    if (ws.spacing == 0.0) ws.spacing = s.spacing;
    if (ws.spacing > 0.5 * length)
      r.fail(key + ".spacing", fmt::format("= {} m: a wall {:.4g} m long needs a smaller spacing",
                                           ws.spacing, length));
    ws.strength = r.non_negative(key + ".strength");
    if (ws.strength == 0.0) ws.strength = 5.0 * gravity_magnitude(s) * tallest_water(s);
    ws.cutoff = r.non_negative(key + ".cutoff");
    if (ws.cutoff == 0.0) ws.cutoff = ws.spacing;
    const auto powers = r.numbers(key + ".powers");
    if (powers.size() != 2 || !(powers[0] > powers[1]) || !(powers[1] > 0.0))
      r.fail(key + ".powers", "must be [p1, p2] with p1 > p2 > 0 (p1 = p2 is no force)");
    ws.power_repulsive = powers[0];
    ws.power_attractive = powers[1];
    if (ws.force == "lennard_jones" && !(ws.strength > 0.0))
      r.fail(key + ".strength", "cannot be derived without gravity and water: set it (m^2/s^2)");
    ws.put_back_distance = r.in_range(key + ".put_back_distance", 0.01, 2.0) * s.spacing;
    ws.reach = r.non_negative(key + ".reach") * s.spacing;
    if (ws.reach == 0.0) ws.reach = 2.0 * s.h_over_dx * s.spacing;
    // W (6.11) is evaluated no nearer than the put-back distance (repulsion_monaghan_kos_w610.hpp):
    // with the reach inside it, q never falls below 1 and the wall would never push.
    if (ws.force == "monaghan_kos" && !(ws.reach > ws.put_back_distance))
      r.fail(key + ".reach",
             fmt::format("= {:.4g} m must exceed put_back_distance = {:.4g} m (the force is taken "
                         "no nearer than that: this wall would never push)",
                         ws.reach, ws.put_back_distance));
    ws.clearance = r.non_negative(key + ".clearance");
    if (ws.clearance == 0.0) ws.clearance = ws.force == "lennard_jones" ? ws.cutoff : ws.reach;
    ws.stroke = r.num(key + ".stroke");
    ws.frequency = r.non_negative(key + ".frequency");
    ws.phase = r.num(key + ".phase");
    ws.hinge_depth = r.non_negative(key + ".hinge_depth");
    ws.reference_height = r.positive(key + ".reference_height");
    if (!std::isfinite(ws.stroke) || !std::isfinite(ws.phase))
      r.fail(key + ".stroke", "and phase must be finite");
    if (ws.stroke != 0.0 && !(ws.frequency > 0.0))
      r.fail(key + ".frequency", "must be > 0 for a paddle (stroke is not 0)");
    if (ws.stroke != 0.0) {
      // The paddle must stay inside the box: its top moves by up to the lever times |A|.
      const double top = std::abs(ws.to[1] - ws.from[1]);
      const double reach = 0.5 * (top + ws.hinge_depth) / (ws.reference_height + ws.hinge_depth) *
                           std::abs(ws.stroke);
      for (const auto* end : {&ws.from, &ws.to})
        if ((*end)[0] - reach < s.domain_min[0] || (*end)[0] + reach > s.domain_max[0])
          r.fail(
              key + ".stroke",
              fmt::format("moves the paddle up to {:.4g} m along x, out of the domain box", reach));
    }
    s.repulsive_walls.push_back(ws);
  }
}

namespace {

// validation.convergence_* (CaseSpec): the spacings fall strictly; every block follows
// particles.spacing on the lattice (a random block's resolution is its count, a block with a
// spacing of its own would keep it); the overrides are KEY=VALUE. The curve index is checked
// once the curves are read.
void read_convergence_study(const Reader& r, CaseSpec& s) {
  const std::pair<const char*, std::vector<double>*> studies[] = {
      {"validation.convergence_spacings", &s.convergence_spacings},
      {"validation.quick_convergence_spacings", &s.quick_convergence_spacings}};
  for (const auto& [key, out] : studies) {
    const auto spacings = r.numbers(key);
    if (spacings.size() == 1) r.fail(key, "a study needs at least two spacings (or none)");
    for (std::size_t k = 0; k < spacings.size(); ++k) {
      if (!(spacings[k] > 0.0)) r.fail(key, fmt::format("{} m: must be > 0", spacings[k]));
      if (k > 0 && !(spacings[k] < spacings[k - 1]))
        r.fail(key, fmt::format("{} m after {} m: must fall from coarse to fine", spacings[k],
                                spacings[k - 1]));
    }
    if (!spacings.empty())
      for (std::size_t b = 0; b < s.blocks.size(); ++b)
        if (s.blocks[b].layout != "lattice" || s.blocks[b].spacing > 0.0)
          r.fail(key, fmt::format("fluid_blocks[{}] is not a lattice that follows "
                                  "particles.spacing: the study could not refine it",
                                  b));
    *out = spacings;
  }
  s.convergence_sets = r.strings("validation.convergence_sets");
  for (const auto& o : s.convergence_sets)
    if (o.find('=') == std::string::npos)
      r.fail("validation.convergence_sets", fmt::format("\"{}\" is not KEY=VALUE", o));
  const long curve = r.integer("validation.convergence_curve");
  if (curve < 0) r.fail("validation.convergence_curve", "must be >= 0");
  s.convergence_curve = static_cast<std::size_t>(curve);
}

}  // namespace

void read_validation(const Reader& r, const toml::table& t, const std::filesystem::path& file,
                     CaseSpec& s) {
  s.quick = r.strings("validation.quick");
  s.time_scale = r.positive("validation.time_scale");
  s.notes = r.strings("validation.notes");
  s.variants = r.strings("validation.variants");
  s.quick_variants = r.boolean("validation.quick_variants");
  // Picture times after the end are left out, not refused: a run shortened with
  // --set case.end_time=... keeps working and draws the pictures it has.
  for (double when : r.numbers("validation.pictures")) {
    if (!(when >= 0.0)) r.fail("validation.pictures", fmt::format("{} s: must be >= 0", when));
    if (when <= s.end_time) s.pictures.push_back(when);
  }
  for (double when : r.numbers("validation.crest_pictures")) {
    if (!(when >= 0.0))
      r.fail("validation.crest_pictures", fmt::format("{} s: must be >= 0", when));
    if (!s.waves || s.dimension != 2)
      r.fail("validation.crest_pictures", "needs a 2D wave tank with probes.waves = true");
    if (when <= s.end_time) s.crest_pictures.push_back(when);
  }
  // A field that snapshots hold (run/runner.cpp's snapshot_cloud), or a velocity component;
  // bl41_deviation only comes with a corrected scheme, and a variant may be one.
  {
    std::vector<std::string> fields{"velocity", "velocity_x", "velocity_y",    "density",
                                    "pressure", "mass",       "bl41_deviation"};
    if (s.dimension == 3) fields.push_back("velocity_z");
    if (s.eos == "ideal_gas") fields.push_back("internal_energy");
    s.picture_field = r.one_of("validation.picture_field", fields);
  }
  s.diagnostics_plots = r.strings("validation.diagnostics_plots");
  {
    // A plotted column must be one that diagnostics.csv or the case's probes.csv will hold.
    auto known = probe_names(s);
    const auto diagnostics = s.dimension == 3 ? diagnostics_columns<3>() : diagnostics_columns<2>();
    known.insert(known.end(), diagnostics.begin(), diagnostics.end());
    for (const auto& c : s.diagnostics_plots)
      if (std::find(known.begin(), known.end(), c) == known.end())
        r.fail("validation.diagnostics_plots",
               fmt::format("\"{}\": not a column of diagnostics.csv or probes.csv", c));
  }
  read_convergence_study(r, s);
  for (const auto& v : s.variants) {
    const Variant variant = parse_variant(v);
    if (variant.overrides.empty() || variant.label.empty())
      r.fail("validation.variants",
             fmt::format("\"{}\": each entry is KEY=VALUE, or [LABEL:] KEY=VALUE; KEY=VALUE", v));
    for (const auto& o : variant.overrides)
      if (o.find('=') == std::string::npos)
        r.fail("validation.variants", fmt::format("\"{}\": \"{}\" is not KEY=VALUE", v, o));
  }
  s.companions = r.strings("validation.companions");
  std::vector<std::string> companion_labels;
  for (const auto& c : s.companions) {
    const Variant companion = parse_variant(c);
    if (companion.overrides.empty() || c.find(':') == std::string::npos ||
        c.find(':') > c.find('='))
      r.fail("validation.companions",
             fmt::format("\"{}\": each entry is LABEL: KEY=VALUE; KEY=VALUE ...", c));
    for (const auto& o : companion.overrides)
      if (o.find('=') == std::string::npos)
        r.fail("validation.companions", fmt::format("\"{}\": \"{}\" is not KEY=VALUE", c, o));
    if (std::find(companion_labels.begin(), companion_labels.end(), companion.label) !=
        companion_labels.end())
      r.fail("validation.companions", fmt::format("label \"{}\" given twice", companion.label));
    companion_labels.push_back(companion.label);
  }
  if (const auto* curves = t.at_path("validation.curves").as_array()) {
    for (std::size_t c = 0; c < curves->size(); ++c) {
      const std::string key = fmt::format("validation.curves[{}]", c);
      CurveCheck cc;
      cc.probe = r.one_of(key + ".probe", probe_names(s));
      // probes.crest_profile's columns (crest2_fit_amplitude also needs the second crest).
      const bool profile_column = cc.probe == "crest_width" || cc.probe == "crest_shape" ||
                                  cc.probe.ends_with("fit_amplitude");
      const bool enabled =
          cc.probe == "surge_front"      ? s.surge_front
          : cc.probe == "column_height"  ? s.column_height
          : cc.probe.starts_with("bore") ? s.bore
          : cc.probe.starts_with("semi") ? s.semi_axes
          : profile_column
              ? s.crest_profile && (!cc.probe.starts_with("crest2") || s.second_crest > 0.0)
          : cc.probe.starts_with("crest2")                           ? s.second_crest > 0.0
          : cc.probe.starts_with("crest")                            ? s.waves
          : cc.probe.starts_with("gauge")                            ? s.waves
          : cc.probe.starts_with("density")                          ? s.density_deviation
          : cc.probe.starts_with("centre")                           ? s.centre_of_mass
          : cc.probe == "overturn" || cc.probe.starts_with("broken") ? s.breaking
          : cc.probe == "incident_amplitude" || cc.probe.starts_with("grilli") ? s.beach_slope > 0.0
                                                                               : s.still_water;
      if (!enabled)
        r.fail(key + ".probe",
               fmt::format("= \"{}\": the case's [probes] do not measure it", cc.probe));
      cc.label = r.str(key + ".label");
      const std::string ref = r.str(key + ".reference");
      if (ref.starts_with("theory:")) {
        // A reference solution computed by flume (validation/theory_reference.hpp).
        cc.theory = r.one_of(key + ".reference",
                             {"theory:elliptical_drop", "theory:bore", "theory:kdv",
                              "theory:still_water", "theory:free_fall", "theory:standing_wave"})
                        .substr(7);
        if (cc.theory == "kdv" && !s.waves)
          r.fail(key + ".reference", "= \"theory:kdv\" needs probes.waves = true (crest_x)");
        if (cc.theory == "free_fall" && !s.centre_of_mass)
          r.fail(key + ".reference",
                 "= \"theory:free_fall\" needs probes.centre_of_mass = true (centre_y)");
      } else if (ref == "self") {
        cc.theory = "self";  // validate builds the table: columns t and value
      } else if (ref.starts_with("run:")) {
        cc.theory = "run";  // validate builds the table from the companion: columns t and value
        cc.companion = ref.substr(4);
        if (std::find(companion_labels.begin(), companion_labels.end(), cc.companion) ==
            companion_labels.end())
          r.fail(key + ".reference",
                 fmt::format("= \"{}\": no validation.companions entry is labelled \"{}\"", ref,
                             cc.companion));
        cc.reference_probe = r.str(key + ".reference_probe");
        if (cc.reference_probe.empty()) cc.reference_probe = cc.probe;
        const auto names = probe_names(s);
        if (std::find(names.begin(), names.end(), cc.reference_probe) == names.end())
          r.fail(
              key + ".reference_probe",
              fmt::format("= \"{}\": not a column of the case's probes.csv", cc.reference_probe));
      } else {
        cc.reference = file.parent_path() / ref;
        if (!std::filesystem::exists(cc.reference))
          r.fail(key + ".reference", fmt::format("file {} not found", cc.reference.string()));
      }
      const bool computed_table = cc.theory == "self" || cc.theory == "run";
      cc.reference_x = computed_table ? "t" : r.str(key + ".reference_x");
      cc.reference_y = computed_table ? "value" : r.str(key + ".reference_y");
      cc.source = r.str(key + ".source");
      cc.value_scale = r.positive(key + ".value_scale");
      cc.absolute = r.one_of(key + ".error", {"relative", "absolute"}) == "absolute";
      cc.tolerance = r.positive(key + ".tolerance");
      cc.quick_tolerance = r.positive(key + ".quick_tolerance");
      cc.mean_tolerance = r.non_negative(key + ".mean_tolerance");
      cc.quick_mean_tolerance = r.non_negative(key + ".quick_mean_tolerance");
      cc.gated = r.boolean(key + ".gated");
      const std::string stat =
          r.one_of(key + ".statistic", {"pointwise", "mean", "slope", "max", "line_at", "period"});
      cc.statistic = stat == "mean"      ? CurveStatistic::mean
                     : stat == "slope"   ? CurveStatistic::slope
                     : stat == "max"     ? CurveStatistic::max
                     : stat == "line_at" ? CurveStatistic::line_at
                     : stat == "period"  ? CurveStatistic::period
                                         : CurveStatistic::pointwise;
      cc.at = r.num(key + ".at");
      if (!std::isfinite(cc.at)) r.fail(key + ".at", "must be finite");
      cc.window_from = r.non_negative(key + ".window_from");
      cc.window_to = r.non_negative(key + ".window_to");
      if (cc.window_to != 0.0 && !(cc.window_to > cc.window_from))
        r.fail(key + ".window_to", "must exceed window_from (or be 0: to the last point)");
      cc.reference_from = r.non_negative(key + ".reference_from");
      cc.reference_to = r.non_negative(key + ".reference_to");
      if ((cc.theory == "self" || cc.theory == "kdv") && cc.statistic == CurveStatistic::pointwise)
        r.fail(key + ".statistic",
               fmt::format("= \"pointwise\": reference \"{}\" compares a mean or a slope", ref));
      if (cc.theory == "standing_wave" && cc.statistic != CurveStatistic::period)
        r.fail(key + ".statistic",
               "must be \"period\" with reference \"theory:standing_wave\" (it gives a period)");
      if (cc.theory == "self" && !(cc.reference_to > cc.reference_from))
        r.fail(key + ".reference_to",
               "must exceed reference_from: the window whose statistic is the reference");
      s.curves.push_back(cc);
    }
  }
  if (const auto* profiles = t.at_path("validation.profiles").as_array()) {
    for (std::size_t c = 0; c < profiles->size(); ++c) {
      const std::string key = fmt::format("validation.profiles[{}]", c);
      ProfileCheck pc;
      pc.field = r.one_of(key + ".field", {"rho", "p", "u"});
      pc.theory = r.one_of(key + ".reference", {"theory:riemann"}).substr(7);
      if (!s.profile) r.fail(key, "compares profile.csv: set output.profile = true");
      if (s.eos != "ideal_gas" || s.blocks.size() != 2)
        r.fail(key + ".reference",
               "= \"theory:riemann\" needs an ideal gas in two fluid blocks (left, right)");
      pc.tolerance = r.positive(key + ".tolerance");
      pc.quick_tolerance = r.positive(key + ".quick_tolerance");
      pc.gated = r.boolean(key + ".gated");
      s.profiles.push_back(pc);
    }
  }
  if ((!s.convergence_spacings.empty() || !s.quick_convergence_spacings.empty()) &&
      !(s.convergence_curve < s.curves.size()))
    r.fail("validation.convergence_curve",
           fmt::format("= {}: the study follows one of the case's {} [[validation.curves]]",
                       s.convergence_curve, s.curves.size()));
}

}  // namespace flume
