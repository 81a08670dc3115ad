// Reading a case file: parse TOML, apply --set overrides, reject unknown keys, wrong types and
// out-of-range values with one clear line (InputError: file, key, what is allowed), fill every
// default, and return the resolved CaseSpec.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "flume/case/case_spec.hpp"

namespace flume {

CaseSpec read_case(const std::filesystem::path& file, const std::vector<std::string>& overrides);
CaseSpec read_case_string(const std::string& toml_text, const std::filesystem::path& file,
                          const std::vector<std::string>& overrides);

// The documented defaults of every key, as TOML with comments (for the README and --help).
const std::string& case_defaults_toml(int dimension);

}  // namespace flume
