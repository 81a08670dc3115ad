// The reference curve of a validation check: a CSV file, or a solution flume computes from the
// case itself (`reference = "theory:NAME"` in the case file).
#pragma once

#include "flume/case/case_spec.hpp"
#include "flume/io/csv_table.hpp"

namespace flume {

// The check's reference table. "elliptical_drop": the exact solution of BL 5.2
// (theory/elliptical_drop.hpp) for the case's first fluid block (a circle of radius R0 with
// the velocity gradient diag(-A0, A0)), at 40 times up to the end time: columns t (s), a and
// b (m). "bore": BL (67)-(68). "still_water": rho0 g H and H. "kdv" and "self" are computed
// from the run's own probes (probes.csv): "kdv" the amplitude W (6.16) gives the speed of
// crest_x over the check's window (and KdV's crest track for the amplitude measured there),
// "self" the check's statistic of its probe over reference_from..reference_to. "run" (reference
// = "run:LABEL") is column reference_probe of `companion`, the probes of companion run LABEL
// (nullptr when it did not complete: a table without rows). Throws InputError when the case
// does not fit the solution.
io::CsvData curve_reference(const CaseSpec& spec, const CurveCheck& check,
                            const io::CsvData& probes, const io::CsvData* companion = nullptr);

}  // namespace flume
