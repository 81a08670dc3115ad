// From a resolved TOML table (defaults merged with the user's file) to a CaseSpec: typed values,
// range checks with one clear line per error, and the derived values (scheme rows, EOS).
#pragma once

#include <toml++/toml.h>
#include <filesystem>

#include "flume/case/case_spec.hpp"

namespace flume {

CaseSpec build_spec(const toml::table& resolved, const std::filesystem::path& file, int dim);

// The resolved table with the derived values written back (scheme rows, bulk modulus, sound
// speed), so that the run directory's case.toml repeats the run exactly.
toml::table spec_to_table(const CaseSpec& spec, toml::table resolved);

}  // namespace flume
