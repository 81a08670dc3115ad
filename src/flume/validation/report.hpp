// report.md of `flume validate`: per case, the run details, the papers' own numbers, and per curve
// a table setting the reference beside flume's main run and its variants, with the plot.
#pragma once

#include <string>
#include <vector>

#include "flume/validation/case_result.hpp"

namespace flume {

// report.md is the heading, then each case's section in the order the cases were asked.
std::string report_heading(bool quick);
std::string report_case_section(const CaseResult& cr);

}  // namespace flume
