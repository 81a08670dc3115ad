// report.md of `flume validate`: per case, the run details, the papers' own numbers, and per curve
// a table setting the reference beside flume's main run and its variants, with the plot.
#pragma once

#include <string>
#include <vector>

#include "flume/validation/case_result.hpp"

namespace flume {

std::string report_markdown(const std::vector<CaseResult>& results, bool quick);

}  // namespace flume
