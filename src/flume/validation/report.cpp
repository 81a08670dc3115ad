#include "flume/validation/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flume/validation/report_tables.hpp"

namespace flume {

ErrorSummary summarize(const std::vector<CurvePoint>& points) {
  ErrorSummary s;
  for (const auto& p : points) {
    s.max = std::max(s.max, p.error);
    s.mean += p.error;
  }
  if (!points.empty()) s.mean /= static_cast<double>(points.size());
  return s;
}

namespace {

// A variant's overrides as a run line's note: " (`KEY=VALUE`, ...)"; "" for the case as written.
std::string variant_note(const SeriesResult& s) {
  if (s.overrides.empty()) return "";
  std::string note = " (";
  for (std::size_t k = 0; k < s.overrides.size(); ++k)
    note += (k ? ", `" : "`") + s.overrides[k] + "`";
  return note + ")";
}

// `note` follows the label: " (coarse)" for a convergence run, a variant's overrides.
std::string run_line(const std::string& label, const RunResult& run, double spacing,
                     const std::string& note = "") {
  if (!run.completed) return fmt::format("- `{}`{}: **failed**: {}\n", label, note, run.error);
  return fmt::format(
      "- `{}`{}: {} particles, {} steps, {:.1f} s wall time ({:.3g} particle-steps/s, "
      "{} threads), spacing {} m\n",
      label, note, run.particles, run.steps, run.wall_seconds, run.particle_steps_per_second,
      run.threads, spacing);
}

// flume's value and signed error at reference abscissa x, or dashes where the series has none
// (a failed or shorter variant run).
std::string table_cells(const SeriesResult& s, std::size_t c, double x, bool absolute) {
  if (c >= s.curves.size()) return " - | - |";
  for (const auto& q : s.curves[c]) {
    if (q.x != x) continue;
    if (absolute) return fmt::format(" {:.4f} | {:+.4f} |", q.value, q.value - q.reference);
    return fmt::format(" {:.4f} | {:+.2f} % |", q.value,
                       100 * (q.value - q.reference) / std::abs(q.reference));
  }
  return " - | - |";
}

// An error or tolerance as the curve measures it: a percentage, or a number in its units.
std::string amount(double e, bool absolute) {
  return absolute ? fmt::format("{:.3f}", e) : fmt::format("{:.1f} %", 100 * e);
}

std::string curve_section(const CaseResult& cr, std::size_t c) {
  const auto& check = cr.spec.curves[c];
  const auto& main = cr.series.front();
  const auto main_sum = summarize(main.curves[c]);
  const double mean_tol = cr.mean_tolerances[c];
  const bool pass = !main.curves[c].empty() && main_sum.max <= cr.tolerances[c] &&
                    (mean_tol <= 0.0 || main_sum.mean <= mean_tol);
  const bool abs = check.absolute;
  const std::string bounds = mean_tol > 0.0
                                 ? fmt::format("tolerance {} (max), {} (mean)",
                                               amount(cr.tolerances[c], abs), amount(mean_tol, abs))
                                 : fmt::format("tolerance {}", amount(cr.tolerances[c], abs));
  const std::string verdict = check.gated
                                  ? fmt::format("{}: **{}**", bounds, pass ? "pass" : "FAIL")
                                  : std::string("reported, not gated");
  std::string md = fmt::format(
      "\n### {}\n\nReference: {} (`{}`). Error {}. The case as written (`{}`): {} points, max "
      "error {}, mean {}, {}.\n",
      check.label, check.source,
      check.theory.empty()     ? check.reference.filename().string()
      : check.theory == "run"  ? "run:" + check.companion
      : check.theory == "self" ? std::string("self")
                               : "theory:" + check.theory,
      abs ? "absolute, in the reference's units" : "relative", main.label, main.curves[c].size(),
      amount(main_sum.max, abs), amount(main_sum.mean, abs), verdict);
  for (std::size_t v = 1; v < cr.series.size(); ++v) {
    const auto& s = cr.series[v];
    if (!s.run.completed) continue;
    const auto sum = summarize(s.curves[c]);
    md += fmt::format("Variant `{}`: max error {}, mean {} (reported, not gated).\n", s.label,
                      amount(sum.max, abs), amount(sum.mean, abs));
  }
  if (check.statistic == CurveStatistic::period)
    md += fmt::format(
        "Compared: the mean period of every output of the run with {} from {:.3g} to the row's "
        "{} (the mean interval between the upward crossings of its mean) against the "
        "reference's.\n",
        check.reference_x, check.window_from, check.reference_x);
  else if (check.statistic != CurveStatistic::pointwise)
    md += fmt::format(
        "Compared: the {} of the values at the reference's points with {} from {:.3g} to the "
        "row's {}.\n",
        check.statistic == CurveStatistic::slope ? std::string("least-squares slope (per unit x)")
        : check.statistic == CurveStatistic::line_at
            ? fmt::format("least-squares line's value at {} = {:.4g}", check.reference_x, check.at)
            : std::string(statistic_name(check.statistic)),
        check.reference_x, check.window_from, check.reference_x);
  if (check.theory == "self")
    md += fmt::format(
        "The reference is the same statistic of the same run over t = {:.4g}-{:.4g} s.\n",
        check.reference_from, check.reference_to);
  if (check.theory == "run")
    md += fmt::format(
        "The reference is the same statistic of `{}` over the same window in each "
        "configuration's companion run `{}`.\n",
        check.reference_probe, check.companion);
  md += fmt::format("\n| {} | reference {} |", check.reference_x, check.reference_y);
  std::string rule = "\n|---|---|";
  for (const auto& s : cr.series) {
    md += fmt::format(" `{}` | error |", s.label);
    rule += "---|---|";
  }
  md += rule + "\n";
  for (std::size_t k = 0; k < main.curves[c].size(); ++k) {
    const auto& p = main.curves[c][k];
    md += fmt::format("| {:.3g} | {:.3g} |", p.x, p.reference);
    for (const auto& s : cr.series)
      md += table_cells(s, c, p.x, abs);
    md += "\n";
  }
  md += cr.plots[c].empty() ? "\n(plot unavailable: python3 with matplotlib not found)\n"
                            : fmt::format("\n![{}]({})\n", check.label, cr.plots[c]);
  return md;
}

std::string diagnostics_section(const CaseResult& cr) {
  std::string md;
  for (std::size_t k = 0; k < cr.diagnostics_plots.size(); ++k) {
    const auto& column = cr.spec.diagnostics_plots[k];
    md += fmt::format("\n### {} of every scheme\n\n", column);
    md += cr.diagnostics_plots[k].empty()
              ? "(plot unavailable: python3 with matplotlib not found)\n"
              : fmt::format("![{}]({})\n", column, cr.diagnostics_plots[k]);
  }
  return md;
}

std::string pictures_section(const CaseResult& cr) {
  if (cr.pictures.empty()) return "";
  std::string md =
      fmt::format("\n### Particles, coloured by {} (the snapshot nearest each time)\n\n| t (s) |",
                  cr.spec.picture_field);
  std::string rule = "\n|---|";
  for (const auto& s : cr.series) {
    md += fmt::format(" `{}` |", s.label);
    rule += "---|";
  }
  md += rule + "\n";
  for (std::size_t k = 0; k < cr.pictures.size(); ++k) {
    md += fmt::format("| {:.4g} |", cr.spec.pictures[k]);
    for (const auto& png : cr.pictures[k])
      md += png.empty() ? " (unavailable) |" : fmt::format(" ![]({}) |", png);
    md += "\n";
  }
  return md;
}

// The crest profiles against KdV's sech^2 (validate's draw_crest_profiles).
std::string crest_pictures_section(const CaseResult& cr) {
  if (cr.crest_pictures.empty()) return "";
  std::string md =
      "\n### The surface near the crest against KdV's A sech^2((x - x_c) / lambda)\n\n"
      "The depth of water from the particles' masses (as the wave probes read it), against x - x_c "
      "about the highest crest, for every scheme at the snapshot nearest each time; dashed: KdV's "
      "wave of the height measured, lambda = sqrt(4 H^3 / (3 A)) (W (6.17)).\n\n";
  for (std::size_t k = 0; k < cr.crest_pictures.size(); ++k)
    md +=
        cr.crest_pictures[k].empty()
            ? fmt::format("- t = {:.4g} s: (unavailable)\n", cr.spec.crest_pictures[k])
            : fmt::format("![t = {:.4g} s]({})\n", cr.spec.crest_pictures[k], cr.crest_pictures[k]);
  return md;
}

}  // namespace

// The relative L1 errors of every series against the exact solution, one row per field, and
// the profile plots (W Figs 4.1-4.3).
std::string profile_section(const CaseResult& cr) {
  if (cr.spec.profiles.empty()) return "";
  std::string md = fmt::format(
      "\n### Profiles at t = {} s against the exact Riemann solution\n\nRelative L1 error "
      "sum |f - f_exact| / sum |f_exact| over the particles within {} spacings of the line; the "
      "case as written (`{}`) is gated, the variants reported.\n\n| field | tolerance |",
      cr.spec.end_time, cr.spec.profile_band, cr.series.front().label);
  std::string rule = "\n|---|---|";
  for (const auto& s : cr.series) {
    md += fmt::format(" `{}` |", s.label);
    rule += "---|";
  }
  md += rule + "\n";
  for (std::size_t c = 0; c < cr.spec.profiles.size(); ++c) {
    md +=
        fmt::format("| {} | {:.1f} % |", cr.spec.profiles[c].field, 100 * cr.profile_tolerances[c]);
    for (const auto& s : cr.series)
      md += s.run.completed && c < s.profile_errors.size()
                ? fmt::format(" {:.2f} % |", 100 * s.profile_errors[c])
                : std::string(" failed |");
    md += "\n";
  }
  for (std::size_t c = 0; c < cr.profile_plots.size(); ++c)
    md += cr.profile_plots[c].empty()
              ? "\n(plot unavailable: python3 with matplotlib not found)\n"
              : fmt::format("\n![{}]({})\n", cr.spec.profiles[c].field, cr.profile_plots[c]);
  return md;
}

std::string report_heading(bool quick) {
  return fmt::format(
      "# flume validation report\n\nflume {}{}. Errors are relative, |flume - reference| / "
      "|reference|, unless a curve says absolute; in the tables they are signed (positive: flume "
      "ahead of / above the reference).\n",
      FLUME_VERSION, quick ? ", quick (reduced-resolution) set" : "");
}

std::string report_case_section(const CaseResult& cr) {
  std::string md =
      fmt::format("\n## {}\n\n{}\n\nRuns (scheme, kernel `{}`, h/dx = {}):\n\n", cr.spec.name,
                  cr.spec.description, cr.spec.kernel, cr.spec.h_over_dx);
  for (const auto& s : cr.series)
    md += run_line(s.label, s.run, cr.spec.spacing, variant_note(s));
  for (const auto& s : cr.series)
    for (const auto& [companion, run] : s.companions)
      md += run_line(s.label + "/" + companion, run, cr.spec.spacing,
                     " (companion: the reference of the curves with run:" + companion + ")");
  if (cr.coarse_spacing > 0.0)
    for (const auto& s : cr.series)
      md += run_line(s.label, s.coarse_run, cr.coarse_spacing, " (coarse)");
  for (const auto& level : cr.study)
    md += run_line(cr.spec.preset, level.run, level.spacing, " (convergence study)");
  if (!cr.overrides.empty()) {
    md += "\nEvery run with `--set`:";
    for (const auto& o : cr.overrides)
      md += " `" + o + "`";
    md += " (not the case as bundled).\n";
  }
  if (!cr.spec.notes.empty()) {
    md += "\nWhat the papers report:\n\n";
    for (const auto& n : cr.spec.notes)
      md += "- " + n + "\n";
  }
  if (!cr.series.front().run.completed) return md;
  for (std::size_t c = 0; c < cr.spec.curves.size(); ++c)
    md += curve_section(cr, c);
  md += schemes_section(cr) + profile_section(cr) + convergence_section(cr) + study_section(cr) +
        diagnostics_section(cr) + pictures_section(cr) + crest_pictures_section(cr);
  return md;
}

}  // namespace flume
