// The second, coarser resolution of a profile case (W-1's "converge under resolution
// refinement"): the overrides that double every lattice spacing of the resolution validated, and
// the order observed between the two.
#pragma once

#include <string>
#include <vector>

#include "flume/case/case_spec.hpp"

namespace flume {

// --set overrides that run `spec` at twice its spacing: particles.spacing and every lattice
// block's own spacing doubled (a block with spacing 0 follows particles.spacing). Derived from the
// spec as resolved (after --quick and --set), so it is always the validated run's coarser twin.
// Empty when no coarser twin exists: a random block's particle count is its own key, not a
// spacing, so doubling its spacing would not coarsen it.
std::vector<std::string> coarser_overrides(const CaseSpec& spec);

// The --set override that runs a case at `spacing` (a level of a convergence study):
// particles.spacing, written as a TOML float.
std::string spacing_override(double spacing);

// The order of convergence between two levels of a study: log(coarse_error / fine_error) /
// log(coarse_spacing / fine_spacing). NaN when an error is not positive and finite.
double observed_order(double coarse_error, double fine_error, double coarse_spacing,
                      double fine_spacing);

// log2(coarse / fine): the order of convergence seen when the spacing halves (1 for an error
// proportional to the spacing). NaN when either error is not positive and finite.
double observed_order(double coarse_error, double fine_error);

}  // namespace flume
