#include "flume/validation/bundled_cases.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "flume/core/error.hpp"

namespace flume {

std::filesystem::path bundled_cases_dir() {
  if (const char* env = std::getenv("FLUME_CASES_DIR")) return env;
  return std::filesystem::path(FLUME_SOURCE_DIR) / "cases";
}

std::vector<std::filesystem::path> bundled_case_files() {
  std::vector<std::filesystem::path> files;
  const auto dir = bundled_cases_dir();
  if (!std::filesystem::is_directory(dir)) return files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::filesystem::path bundled_case(const std::string& name) {
  const auto file = bundled_cases_dir() / (name + ".toml");
  if (!std::filesystem::exists(file)) {
    std::vector<std::string> names;
    for (const auto& f : bundled_case_files())
      names.push_back(f.stem().string());
    throw InputError(
        fmt::format("no bundled case named '{}' (available: {})", name, fmt::join(names, ", ")));
  }
  return file;
}

}  // namespace flume
