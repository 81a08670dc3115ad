// The reference curve of a validation check: a CSV file, or a solution flume computes from the
// case itself (`reference = "theory:NAME"` in the case file).
#pragma once

#include "flume/case/case_spec.hpp"
#include "flume/io/csv_table.hpp"

namespace flume {

// The check's reference table. "elliptical_drop": the exact solution of BL 5.2
// (theory/elliptical_drop.hpp) for the case's first fluid block (a circle of radius R0 with
// the velocity gradient diag(-A0, A0)), at 40 times up to the end time: columns t (s), a and
// b (m). Throws InputError when the case does not fit the solution.
io::CsvData curve_reference(const CaseSpec& spec, const CurveCheck& check);

}  // namespace flume
