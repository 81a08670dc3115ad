// What validating one case produced: the main run (whose metrics pass or fail) and the variant
// runs (other schemes on the same case, reported beside it, as BL Figs 9-11 set standard,
// inconsistent and corrected SPH side by side).
#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "flume/case/case_spec.hpp"
#include "flume/run/runner.hpp"
#include "flume/validation/curve_compare.hpp"
#include "flume/validation/density_range.hpp"

namespace flume {

struct SeriesResult {
  std::string label;  // "main" configuration's preset, or the variant's override value
  std::vector<std::string> overrides;  // a variant's KEY=VALUE (empty for the case as written)
  RunResult run;
  std::vector<std::vector<CurvePoint>> curves;  // one per CaseSpec::curves entry
  std::vector<double> profile_errors;           // one per CaseSpec::profiles entry (L1)
  // The same configuration at twice the spacing (profile cases: convergence.hpp); run only when
  // CaseResult::coarse_spacing > 0.
  RunResult coarse_run;
  std::vector<double> coarse_profile_errors;  // one per CaseSpec::profiles entry (L1)
  // A liquid's density over the run, from diagnostics.csv (has_density_range false for a gas).
  bool has_density_range = false;
  DensityRange density;
  // The companion runs of this configuration (CaseSpec::companions, in order): the references
  // of the curves with reference = "run:LABEL".
  std::vector<std::pair<std::string, RunResult>> companions;
};

// One run of a convergence study (CaseSpec::convergence_spacings): the case as written at one
// spacing, and the largest error over its points of the curve the study follows.
struct StudyLevel {
  double spacing = 0.0;  // m
  RunResult run;
  double max_error = std::numeric_limits<double>::quiet_NaN();  // NaN: no point compared
};

struct CaseResult {
  CaseSpec spec;
  std::vector<SeriesResult> series;     // [0] is the case as written; then the variants
  std::vector<double> tolerances;       // per curve (quick or full): bound on the max error
  std::vector<double> mean_tolerances;  // per curve: bound on the mean error (0 = none)
  std::vector<std::string> plots;       // per curve: PNG file name, empty if plotting failed
  std::vector<std::string> overrides;   // --set KEY=VALUE given to validate, in every run
  // pictures[k][s]: PNG of series s near spec.pictures[k] ("" if it could not be drawn)
  std::vector<std::vector<std::string>> pictures;
  std::vector<std::string> crest_pictures;     // per spec.crest_pictures entry: PNG or ""
  std::vector<std::string> diagnostics_plots;  // per spec.diagnostics_plots entry: PNG or ""
  std::vector<double> profile_tolerances;      // per profile check (quick or full)
  std::vector<std::string> profile_plots;      // per profile check: PNG or ""
  double coarse_spacing = 0.0;    // m, particles.spacing of the coarser runs; 0 = none run
  std::vector<StudyLevel> study;  // the convergence study, coarse to fine (empty: none run)
};

// Max and mean of the errors of a curve.
struct ErrorSummary {
  double max = 0.0;
  double mean = 0.0;
};
ErrorSummary summarize(const std::vector<CurvePoint>& points);

}  // namespace flume
