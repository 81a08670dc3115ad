// The named presets of spec/methods.md and the row combinations that have a scheme (declared
// in registry.hpp). Apart from make_scheme, so that what reads case files (and the case
// reader's fuzzer, fuzz/) does not need the schemes themselves.
#include <map>

#include "flume/schemes/registry.hpp"

namespace flume {

namespace {
const std::map<std::string, SchemeRows>& presets() {
  static const std::map<std::string, SchemeRows> table{
      {"standard", {"summation", "bl7", "none"}},
      {"continuity", {"continuity", "bl20", "none"}},
      {"inconsistent", {"summation", "bl20", "none"}},
      {"csph", {"continuity", "bl59", "mixed"}},
      {"sph-euler", {"w350", "w351", "none"}},
      {"wsph", {"w379", "w380", "none"}},
      {"rsph", {"w379", "w380", "renormalized"}},
      // W 6 calls it LES-SPH: weak SPH with the sub-grid stress, W (5.33)-(5.34).
      {"les-sph", {"w379", "w380", "none", "fixed", "smagorinsky"}},
  };
  return table;
}
}  // namespace

std::optional<SchemeRows> preset_rows(const std::string& preset) {
  auto it = presets().find(preset);
  if (it == presets().end()) return std::nullopt;
  return it->second;
}

const std::vector<std::string>& preset_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& [k, v] : presets())
      n.push_back(k);
    return n;
  }();
  return names;
}

const std::vector<std::string>& scheme_combinations() {
  static const std::vector<std::string> combos{
      "summation+bl7+none",    "summation+bl7+shepard",    "summation+bl7+first_order",
      "summation+bl20+none",   "summation+bl20+shepard",   "summation+bl20+first_order",
      "continuity+bl20+none",  "continuity+bl20+gradient", "continuity+bl20+shepard",
      "continuity+bl20+mixed", "continuity+bl59+mixed",    "w350+w351+none",
      "w379+w380+none",        "w379+w380+renormalized"};
  return combos;
}

}  // namespace flume
