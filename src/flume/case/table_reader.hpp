// Typed access to a resolved case table, one clear line per error ("FILE: KEY: what is wrong"),
// shared by the readers of the case file's sections (case_checks.cpp, case_sections.cpp).
#pragma once

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "flume/case/case_spec.hpp"
#include "flume/core/error.hpp"

namespace flume {

class Reader {
 public:
  Reader(const toml::table& t, std::string file) : t_(t), file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(fmt::format("{}: {}: {}", file_, key, what));
  }

  const toml::node& node(const std::string& key) const {
    auto v = t_.at_path(key);
    if (!v) fail(key, "missing");
    return *v.node();
  }
  double num(const std::string& key) const {
    const auto& n = node(key);
    if (auto d = n.value<double>()) return *d;
    fail(key, "must be a number");
  }
  long integer(const std::string& key) const {
    return static_cast<long>(*node(key).value<int64_t>());
  }
  bool boolean(const std::string& key) const { return *node(key).value<bool>(); }
  std::string str(const std::string& key) const { return *node(key).value<std::string>(); }
  std::vector<double> vec(const std::string& key) const {
    std::vector<double> out;
    for (const auto& e : *node(key).as_array())
      out.push_back(*e.value<double>());
    for (double x : out)
      if (!std::isfinite(x)) fail(key, "must be finite");
    return out;
  }
  std::vector<std::string> strings(const std::string& key) const {
    std::vector<std::string> out;
    for (const auto& e : *node(key).as_array()) {
      if (!e.is_string()) fail(key, "must be an array of strings");
      out.push_back(*e.value<std::string>());
    }
    return out;
  }
  std::vector<double> numbers(const std::string& key) const {
    std::vector<double> out;
    for (const auto& e : *node(key).as_array()) {
      if (!e.is_number()) fail(key, "must be an array of numbers");
      out.push_back(*e.value<double>());
      if (!std::isfinite(out.back())) fail(key, "must be finite");
    }
    return out;
  }

  double positive(const std::string& key) const {
    const double x = num(key);
    if (!(x > 0.0) || !std::isfinite(x)) fail(key, fmt::format("= {}: must be > 0", x));
    return x;
  }
  double non_negative(const std::string& key) const {
    const double x = num(key);
    if (!(x >= 0.0) || !std::isfinite(x)) fail(key, fmt::format("= {}: must be >= 0", x));
    return x;
  }
  double in_range(const std::string& key, double lo, double hi) const {
    const double x = num(key);
    if (!(x >= lo && x <= hi)) fail(key, fmt::format("= {}: must be in [{}, {}]", x, lo, hi));
    return x;
  }
  std::string one_of(const std::string& key, const std::vector<std::string>& allowed) const {
    const std::string s = str(key);
    if (std::find(allowed.begin(), allowed.end(), s) == allowed.end())
      fail(key, fmt::format("= \"{}\": must be one of {}", s, fmt::join(allowed, ", ")));
    return s;
  }

 private:
  const toml::table& t_;
  std::string file_;
};

inline const char* axis_name(int k) {
  return k == 0 ? "x" : k == 1 ? "y" : "z";
}

// The readers of the case file's later sections, in case_sections.cpp: [probes], and
// [validation] with its curves and profiles (after the fluid blocks and the output section,
// whose values they check against).
void read_probes(const Reader& r, CaseSpec& s);
// [[repulsive_walls]] (after the fluid blocks and the sound speed, which its defaults use).
void read_repulsive_walls(const Reader& r, const toml::table& t, CaseSpec& s);
void read_validation(const Reader& r, const toml::table& t, const std::filesystem::path& file,
                     CaseSpec& s);

}  // namespace flume
