// A variant of a validation case (validation.variants): another configuration of the same case,
// run and reported beside it. Written "KEY=VALUE", or several overrides separated by ';' with
// an optional label before a ':' ("les-sph: scheme.preset=les-sph; scheme.alpha=0.0"). The
// label names the variant's run directory and its rows in the report; without one it is the
// first override's value ("scheme.preset=csph" -> "csph").
#pragma once

#include <string>
#include <vector>

namespace flume {

struct Variant {
  std::string label;
  std::vector<std::string> overrides;  // KEY=VALUE each
};

inline std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

inline Variant parse_variant(const std::string& text) {
  Variant v;
  std::string rest = text;
  const auto colon = text.find(':'), eq = text.find('=');
  if (colon != std::string::npos && (eq == std::string::npos || colon < eq)) {
    v.label = trimmed(text.substr(0, colon));
    rest = text.substr(colon + 1);
  }
  std::size_t at = 0;
  while (at <= rest.size()) {
    const auto semi = rest.find(';', at);
    const std::string part =
        trimmed(rest.substr(at, semi == std::string::npos ? std::string::npos : semi - at));
    if (!part.empty()) v.overrides.push_back(part);
    if (semi == std::string::npos) break;
    at = semi + 1;
  }
  if (v.label.empty() && !v.overrides.empty()) {
    const auto& first = v.overrides.front();
    const auto e = first.find('=');
    v.label = e == std::string::npos ? first : first.substr(e + 1);
  }
  return v;
}

}  // namespace flume
