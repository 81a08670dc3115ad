// Two report.md tables that set the schemes of a case side by side: a profile case's L1 errors at
// two resolutions with the order observed, and a liquid case's curve errors with the density
// range each scheme kept.
#pragma once

#include <string>

#include "flume/validation/case_result.hpp"

namespace flume {

// Scheme x field: the L1 error at twice the spacing and at the validated spacing, their ratio and
// the order log2(coarse / fine). Empty when no coarser runs were made.
std::string convergence_section(const CaseResult& cr);

// The convergence study's table (CaseResult::study): spacing, particles, the followed curve's
// largest error and the order between levels; "" when no study ran.
std::string study_section(const CaseResult& cr);

// Per scheme: max and mean error of each curve, and (rho_max - rho0)/rho0, (rho_min - rho0)/rho0
// at their extremes over the run. Empty for a case without curves.
std::string schemes_section(const CaseResult& cr);

}  // namespace flume
