#include "flume/validation/convergence_rows.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace flume {

bool add_convergence_rows(const CaseResult& cr, nlohmann::ordered_json& rows) {
  if (!(cr.coarse_spacing > 0.0)) return true;
  bool all_pass = true;
  for (std::size_t v = 0; v < cr.series.size(); ++v) {
    const auto& s = cr.series[v];
    for (std::size_t c = 0; c < cr.spec.profiles.size(); ++c) {
      const auto& check = cr.spec.profiles[c];
      const std::string metric =
          fmt::format("{} relative L1 error of `{}` falls when the spacing halves ({} m -> {} m)",
                      check.field, s.label, cr.coarse_spacing, cr.spec.spacing);
      const bool ran = c < s.profile_errors.size() && c < s.coarse_profile_errors.size();
      // The row's error is the ratio fine / coarse, below 1 when the error falls. Only that is
      // required, not an order: across a shock and a contact an L1 error falls asymptotically at
      // first order at best (one half at a contact), so no order can be required in general; the
      // report gives the order measured.
      const double fine = ran ? s.profile_errors[c] : 0.0,
                   coarse = ran ? s.coarse_profile_errors[c] : 0.0;
      const double ratio = ran && coarse > 0.0 ? fine / coarse : 0.0;
      const bool pass = ran && coarse > 0.0 && ratio < 1.0;
      // A variant that did not complete a run has no error to converge: its failure is reported
      // (the row fails, the report says why) but, as for its own profile rows, not gated. The
      // case as written is gated either way.
      const bool gated = check.gated && (v == 0 || ran);
      if (gated) all_pass = all_pass && pass;
      nlohmann::ordered_json row{{"case", cr.spec.name}, {"metric", metric}};
      if (ran) {
        row["value"] = fine;
        row["reference"] = coarse;
        row["error"] = ratio;
      } else {
        row["value"] = nullptr;
        row["reference"] = nullptr;
        row["error"] = !s.run.completed ? s.run.error : s.coarse_run.error;
      }
      row["tolerance"] = 1.0;
      row["gated"] = gated;
      row["pass"] = pass;
      rows.push_back(row);
    }
  }
  return all_pass;
}

bool add_study_rows(const CaseResult& cr, nlohmann::ordered_json& rows) {
  bool all_pass = true;
  for (std::size_t k = 1; k < cr.study.size(); ++k) {
    const StudyLevel& coarse = cr.study[k - 1];
    const StudyLevel& fine = cr.study[k];
    const auto& check = cr.spec.curves.at(cr.spec.convergence_curve);
    const auto usable = [](const StudyLevel& l) {
      return l.run.completed && std::isfinite(l.max_error);
    };
    const bool ran = usable(coarse) && usable(fine);
    // Only a fall is required, not an order: the study's runs carry errors that do not fall
    // with the spacing (the fluid's compressibility, the time step) which the study's overrides
    // make small but not zero; the report gives the order measured.
    const double ratio = ran && coarse.max_error > 0.0 ? fine.max_error / coarse.max_error : 0.0;
    const bool pass = ran && coarse.max_error > 0.0 && ratio < 1.0;
    all_pass = all_pass && pass;
    nlohmann::ordered_json row{
        {"case", cr.spec.name},
        {"metric", fmt::format("{} largest error against {} falls when the spacing goes from {} m "
                               "to {} m (convergence study)",
                               check.probe, check.source, coarse.spacing, fine.spacing)}};
    if (ran) {
      row["value"] = fine.max_error;
      row["reference"] = coarse.max_error;
      row["error"] = ratio;
    } else {
      row["value"] = nullptr;
      row["reference"] = nullptr;
      const StudyLevel& failed = usable(coarse) ? fine : coarse;
      row["error"] =
          failed.run.completed ? std::string("no point of the curve compared") : failed.run.error;
    }
    row["tolerance"] = 1.0;
    row["gated"] = true;
    row["pass"] = pass;
    rows.push_back(row);
  }
  return all_pass;
}

}  // namespace flume
