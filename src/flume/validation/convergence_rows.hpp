// results.json rows of a profile case's convergence: for every scheme (the case as written and
// each variant) and field, the L1 error at the validated spacing must be below the error at twice
// that spacing (W-1: "converge under resolution refinement"; issue 8: every error falls when the
// resolution doubles).
#pragma once

#include <nlohmann/json.hpp>

#include "flume/validation/case_result.hpp"

namespace flume {

// Appends one row per scheme and profile check when coarser runs were made; returns false when a
// gated row fails. A run that did not complete fails its rows; they are gated for the case as
// written and reported for a variant (whose runs are reported, not gated, everywhere).
bool add_convergence_rows(const CaseResult& cr, nlohmann::ordered_json& rows);

// Appends one row per step of the case's convergence study (CaseResult::study, coarse to fine):
// the followed curve's largest error at the finer spacing over that at the coarser one, which must
// be below 1. A level that did not complete fails the rows it is part of. Returns false when a
// row fails (every row is gated: the study runs the case as written).
bool add_study_rows(const CaseResult& cr, nlohmann::ordered_json& rows);

}  // namespace flume
