#include "flume/validation/convergence.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace flume {

namespace {
// A spacing as a TOML float: "{}" prints the shortest text that reads back as the same double,
// which for a whole number has no decimal point and would read as a TOML integer.
std::string toml_float(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}
}  // namespace

std::vector<std::string> coarser_overrides(const CaseSpec& spec) {
  for (const auto& b : spec.blocks)
    if (b.layout != "lattice") return {};
  std::vector<std::string> sets{"particles.spacing=" + toml_float(2.0 * spec.spacing)};
  for (std::size_t k = 0; k < spec.blocks.size(); ++k)
    if (spec.blocks[k].spacing > 0.0)
      sets.push_back(
          fmt::format("fluid_blocks[{}].spacing={}", k, toml_float(2.0 * spec.blocks[k].spacing)));
  return sets;
}

std::string spacing_override(double spacing) {
  return "particles.spacing=" + toml_float(spacing);
}

double observed_order(double coarse_error, double fine_error, double coarse_spacing,
                      double fine_spacing) {
  return observed_order(coarse_error, fine_error) / std::log2(coarse_spacing / fine_spacing);
}

double observed_order(double coarse_error, double fine_error) {
  const auto usable = [](double e) { return std::isfinite(e) && e > 0.0; };
  if (!usable(coarse_error) || !usable(fine_error)) return std::numeric_limits<double>::quiet_NaN();
  return std::log2(coarse_error / fine_error);
}

}  // namespace flume
