// The readers of the case file's [probes] and [validation] sections (table_reader.hpp).
#include <fmt/format.h>

#include <algorithm>

#include "flume/case/table_reader.hpp"
#include "flume/sim/diagnostics_columns.hpp"
#include "flume/validation/variant.hpp"

namespace flume {

namespace {

// The probes.csv columns a curve may compare (those the case's [probes] measure are checked
// separately, with a message naming the probe).
std::vector<std::string> probe_names(const CaseSpec& s) {
  std::vector<std::string> names{
      "surge_front",       "column_height", "semi_axis_x",     "semi_axis_y",  "bore_front",
      "bore_height",       "crest_x",       "crest_amplitude", "bed_pressure", "water_level",
      "density_deviation", "centre_x",      "centre_y",        "centre_z",     "overturn",
      "broken_at",         "crest2_x",      "crest2_amplitude"};
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
}

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
  s.picture_field = r.str("validation.picture_field");
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
  for (const auto& v : s.variants) {
    const Variant variant = parse_variant(v);
    if (variant.overrides.empty() || variant.label.empty())
      r.fail("validation.variants",
             fmt::format("\"{}\": each entry is KEY=VALUE, or [LABEL:] KEY=VALUE; KEY=VALUE", v));
    for (const auto& o : variant.overrides)
      if (o.find('=') == std::string::npos)
        r.fail("validation.variants", fmt::format("\"{}\": \"{}\" is not KEY=VALUE", v, o));
  }
  if (const auto* curves = t.at_path("validation.curves").as_array()) {
    for (std::size_t c = 0; c < curves->size(); ++c) {
      const std::string key = fmt::format("validation.curves[{}]", c);
      CurveCheck cc;
      cc.probe = r.one_of(key + ".probe", probe_names(s));
      const bool enabled = cc.probe == "surge_front"                           ? s.surge_front
                           : cc.probe == "column_height"                       ? s.column_height
                           : cc.probe.starts_with("bore")                      ? s.bore
                           : cc.probe.starts_with("semi")                      ? s.semi_axes
                           : cc.probe.starts_with("crest")                     ? s.waves
                           : cc.probe.starts_with("gauge")                     ? s.waves
                           : cc.probe.starts_with("density")                   ? s.density_deviation
                           : cc.probe.starts_with("centre")                    ? s.centre_of_mass
                           : cc.probe == "overturn" || cc.probe == "broken_at" ? s.breaking
                                                                               : s.still_water;
      if (!enabled)
        r.fail(key + ".probe",
               fmt::format("= \"{}\": the case's [probes] do not measure it", cc.probe));
      cc.label = r.str(key + ".label");
      const std::string ref = r.str(key + ".reference");
      if (ref.starts_with("theory:")) {
        // A reference solution computed by flume (validation/theory_reference.hpp).
        cc.theory =
            r.one_of(key + ".reference", {"theory:elliptical_drop", "theory:bore", "theory:kdv",
                                          "theory:still_water", "theory:free_fall"})
                .substr(7);
        if (cc.theory == "kdv" && !s.waves)
          r.fail(key + ".reference", "= \"theory:kdv\" needs probes.waves = true (crest_x)");
        if (cc.theory == "free_fall" && !s.centre_of_mass)
          r.fail(key + ".reference",
                 "= \"theory:free_fall\" needs probes.centre_of_mass = true (centre_y)");
      } else if (ref == "self") {
        cc.theory = "self";  // validate builds the table: columns t and value
      } else {
        cc.reference = file.parent_path() / ref;
        if (!std::filesystem::exists(cc.reference))
          r.fail(key + ".reference", fmt::format("file {} not found", cc.reference.string()));
      }
      cc.reference_x = cc.theory == "self" ? "t" : r.str(key + ".reference_x");
      cc.reference_y = cc.theory == "self" ? "value" : r.str(key + ".reference_y");
      cc.source = r.str(key + ".source");
      cc.value_scale = r.positive(key + ".value_scale");
      cc.absolute = r.one_of(key + ".error", {"relative", "absolute"}) == "absolute";
      cc.tolerance = r.positive(key + ".tolerance");
      cc.quick_tolerance = r.positive(key + ".quick_tolerance");
      cc.mean_tolerance = r.non_negative(key + ".mean_tolerance");
      cc.quick_mean_tolerance = r.non_negative(key + ".quick_mean_tolerance");
      cc.gated = r.boolean(key + ".gated");
      const std::string stat = r.one_of(key + ".statistic", {"pointwise", "mean", "slope", "max"});
      cc.statistic = stat == "mean"    ? CurveStatistic::mean
                     : stat == "slope" ? CurveStatistic::slope
                     : stat == "max"   ? CurveStatistic::max
                                       : CurveStatistic::pointwise;
      cc.window_from = r.non_negative(key + ".window_from");
      cc.window_to = r.non_negative(key + ".window_to");
      if (cc.window_to != 0.0 && !(cc.window_to > cc.window_from))
        r.fail(key + ".window_to", "must exceed window_from (or be 0: to the last point)");
      cc.reference_from = r.non_negative(key + ".reference_from");
      cc.reference_to = r.non_negative(key + ".reference_to");
      if ((cc.theory == "self" || cc.theory == "kdv") && cc.statistic == CurveStatistic::pointwise)
        r.fail(key + ".statistic",
               fmt::format("= \"pointwise\": reference \"{}\" compares a mean or a slope", ref));
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
}

}  // namespace flume
