// Small case files for the tests, built as TOML text so each test states its set-up in full.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "flume/boundaries/box_walls.hpp"
#include "flume/case/case_reader.hpp"
#include "flume/core/error.hpp"

namespace flume::test {

// A water column of width and height `a` at the left wall of a tank 4a x 2a, free-slip walls:
// the dam break of BL 5.3 at a coarse resolution (`n` particles per side).
inline std::string dam_break_toml(const std::string& preset, int n, double end_time,
                                  double a = 0.05715) {
  return fmt::format(R"(
[case]
name = "small_dam_break"
end_time = {end}
[particles]
spacing = {dx}
[scheme]
preset = "{preset}"
[fluid]
viscosity = 0.5
[domain]
min = [0.0, 0.0]
max = [{lx}, {ly}]
[[fluid_blocks]]
min = [0.0, 0.0]
max = [{a}, {a}]
[output]
interval = {end}
snapshot_interval = 0.0
[probes]
surge_front = true
column_height = true
)",
                     fmt::arg("end", end_time), fmt::arg("dx", a / n), fmt::arg("preset", preset),
                     fmt::arg("lx", 4 * a), fmt::arg("ly", 2 * a), fmt::arg("a", a));
}

// A [[validation.curves]] entry for dam_break_toml's case: its column height against the
// `height` column of ref.csv (beside the case file, against `t`), in units of the default a.
inline std::string column_height_curve_toml() {
  return R"(
[[validation.curves]]
probe = "column_height"
reference = "ref.csv"
reference_x = "t"
reference_y = "height"
value_scale = 0.05715
)";
}

// A box [lo, hi]^D with every side open: no ghosts, no wall forces.
template <int D>
BoxWalls<D> open_box(double lo, double hi) {
  BoxWalls<D> walls;
  for (int k = 0; k < D; ++k) {
    walls.lo[k] = lo;
    walls.hi[k] = hi;
  }
  for (auto& axis : walls.kind)
    axis = {WallKind::open, WallKind::open};
  return walls;
}

inline CaseSpec spec_from(const std::string& toml, const std::vector<std::string>& sets = {}) {
  return read_case_string(toml, "test.toml", sets);
}

// An InputError message as the contract wants it: one line, starting with the file name
// (test.toml), holding every part.
inline void expect_one_line_with(const std::string& msg, std::initializer_list<std::string> parts) {
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  EXPECT_EQ(msg.rfind("test.toml", 0), 0u) << "must start with the file name: " << msg;
  for (const auto& p : parts)
    EXPECT_NE(msg.find(p), std::string::npos) << p << " in: " << msg;
}

// The message of the InputError that reading `toml` (with overrides) throws, or "(no error)".
inline std::string error_of(const std::string& toml, const std::vector<std::string>& sets = {}) {
  try {
    spec_from(toml, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace flume::test
