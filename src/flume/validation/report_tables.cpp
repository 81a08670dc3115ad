#include "flume/validation/report_tables.hpp"

#include <fmt/format.h>

#include <cmath>

#include "flume/validation/convergence.hpp"

namespace flume {

namespace {
std::string percent(double e) {
  return fmt::format("{:.2f} %", 100 * e);
}
}  // namespace

std::string convergence_section(const CaseResult& cr) {
  if (!(cr.coarse_spacing > 0.0)) return "";
  std::string md = fmt::format(
      "\n### Convergence: relative L1 errors at two resolutions\n\nEvery scheme at spacing {} m "
      "(twice the validated one; every lattice spacing doubled) and {} m. Ratio = coarse / fine, "
      "order = log2(ratio) (1: the error halves with the spacing). Gated: the error falls (ratio "
      "> 1) for the case as written and every variant that completes both runs (a failed variant "
      "is reported).\n\n| scheme | field | L1, {} m | L1, {} m | ratio | order |\n"
      "|---|---|---|---|---|---|\n",
      cr.coarse_spacing, cr.spec.spacing, cr.coarse_spacing, cr.spec.spacing);
  for (const auto& s : cr.series) {
    for (std::size_t c = 0; c < cr.spec.profiles.size(); ++c) {
      const bool fine_ok = c < s.profile_errors.size();
      const bool coarse_ok = c < s.coarse_profile_errors.size();
      md += fmt::format("| `{}` | {} | {} | {} |", s.label, cr.spec.profiles[c].field,
                        coarse_ok ? percent(s.coarse_profile_errors[c]) : "failed",
                        fine_ok ? percent(s.profile_errors[c]) : "failed");
      const double order = fine_ok && coarse_ok
                               ? observed_order(s.coarse_profile_errors[c], s.profile_errors[c])
                               : std::nan("");
      md += std::isnan(order) ? std::string(" - | - |\n")
                              : fmt::format(" {:.2f} | {:.2f} |\n", std::exp2(order), order);
    }
  }
  return md;
}

std::string study_section(const CaseResult& cr) {
  if (cr.study.empty()) return "";
  const auto& check = cr.spec.curves.at(cr.spec.convergence_curve);
  std::string sets;
  for (const auto& o : cr.spec.convergence_sets)
    sets += " `" + o + "`";
  std::string md = fmt::format(
      "\n### Convergence study: {} against {}\n\nThe case as written (`{}`) at each spacing{}; "
      "the largest error of the curve over its points ({}). Order = log(error at the coarser "
      "spacing / error at the finer) / log(coarser / finer spacing). Gated: the error falls at "
      "each step.\n\n| spacing (m) | particles | largest error | order |\n|---|---|---|---|\n",
      check.probe, check.source, cr.spec.preset, sets.empty() ? "" : ", with" + sets,
      check.absolute ? "absolute" : "relative");
  for (std::size_t k = 0; k < cr.study.size(); ++k) {
    const StudyLevel& l = cr.study[k];
    if (!l.run.completed) {
      md += fmt::format("| {} | failed: {} | - | - |\n", l.spacing, l.run.error);
      continue;
    }
    const std::string error = !std::isfinite(l.max_error) ? std::string("-")
                              : check.absolute            ? fmt::format("{:.3g}", l.max_error)
                                               : fmt::format("{:.3g} %", 100 * l.max_error);
    const double order = k == 0 ? std::nan("")
                                : observed_order(cr.study[k - 1].max_error, l.max_error,
                                                 cr.study[k - 1].spacing, l.spacing);
    md += fmt::format("| {} | {} | {} | {} |\n", l.spacing, l.run.particles, error,
                      std::isnan(order) ? std::string("-") : fmt::format("{:.2f}", order));
  }
  return md;
}

std::string schemes_section(const CaseResult& cr) {
  if (cr.spec.curves.empty()) return "";
  std::string md = "\n### Every scheme side by side\n\nThe max and mean error of each curve (";
  md +=
      "relative, or absolute in the reference's units where the curve says so) and the density "
      "range over the whole run (diagnostics.csv, the extremes of (rho_max - rho0) / rho0 and "
      "(rho_min - rho0) / rho0 over every output row).\n\n| scheme |";
  std::string rule = "\n|---|";
  for (const auto& check : cr.spec.curves) {
    md += fmt::format(" {} vs {}: max | mean |", check.probe, check.source);
    rule += "---|---|";
  }
  md += " rho_max above rho0 | rho_min below rho0 |" + rule + "---|---|\n";
  for (const auto& s : cr.series) {
    md += fmt::format("| `{}` |", s.label);
    for (std::size_t c = 0; c < cr.spec.curves.size(); ++c) {
      if (!s.run.completed || c >= s.curves.size() || s.curves[c].empty()) {
        md += " failed | - |";
        continue;
      }
      const auto sum = summarize(s.curves[c]);
      md += cr.spec.curves[c].absolute
                ? fmt::format(" {:.3f} | {:.3f} |", sum.max, sum.mean)
                : fmt::format(" {:.1f} % | {:.1f} % |", 100 * sum.max, 100 * sum.mean);
    }
    md += s.has_density_range ? fmt::format(" {:+.2f} % | {:+.2f} % |\n", 100 * s.density.above,
                                            100 * s.density.below)
                              : std::string(" - | - |\n");
  }
  return md;
}

}  // namespace flume
