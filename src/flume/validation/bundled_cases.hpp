// Where the bundled case files are: $FLUME_CASES_DIR if set, else the source tree's cases/.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace flume {

std::filesystem::path bundled_cases_dir();
// Bundled case files, sorted by name.
std::vector<std::filesystem::path> bundled_case_files();
// The bundled case file of this name (cases/<name>.toml); throws InputError if there is none.
std::filesystem::path bundled_case(const std::string& name);

}  // namespace flume
