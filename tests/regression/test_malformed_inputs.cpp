// Malformed input, as a user types it (issue "runs that survive", item 5): each of these case
// files and command lines is refused before a step runs, with exit status 2 and one line on
// stderr that names the file and the key (and no run directory written). Together with
// test_hostile_input.cpp (memory, --out, a directory or binary file as the case) and the case
// reader's own tests, and the fuzzer over the same reader (fuzz/).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/flume_binary.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

namespace fs = std::filesystem;

struct Malformed {
  std::string what;     // the mistake
  std::string args;     // after "run CASE"
  std::string replace;  // text of the case file to replace ("" = none) ...
  std::string with;     // ... by this
  std::string key;      // the key (or option) the message must name
};

const std::vector<Malformed>& malformed() {
  static const std::vector<Malformed> rows{
      {"unknown key", "--set scheme.bogus=1", "", "", "scheme.bogus"},
      {"unknown table", "--set nonsense.key=1", "", "", "nonsense.key"},
      {"negative spacing", "--set particles.spacing=-1", "", "", "particles.spacing"},
      {"a string for a number", "--set scheme.cfl=\\\"x\\\"", "", "", "scheme.cfl"},
      {"unknown preset", "--set scheme.preset=magic", "", "", "scheme.preset"},
      {"unknown kernel", "--set scheme.kernel=box", "", "", "scheme.kernel"},
      {"dimension 4", "--set case.dimension=4", "", "", "case.dimension"},
      {"zero end time", "--set case.end_time=0", "", "", "case.end_time"},
      {"negative fixed step", "--set case.dt=-1", "", "", "case.dt"},
      {"zero smoothing length", "--set scheme.h_over_dx=0", "", "", "scheme.h_over_dx"},
      {"unknown integrator", "--set scheme.integrator=euler", "", "", "scheme.integrator"},
      {"unknown equation of state", "--set eos.kind=vdw", "", "", "eos.kind"},
      {"negative gamma", "--set eos.gamma=-1", "", "", "eos.gamma"},
      {"zero density", "--set fluid.density=0", "", "", "fluid.density"},
      {"negative viscosity", "--set fluid.viscosity=-0.1", "", "", "fluid.viscosity"},
      {"unknown wall", "--set boundaries.x_min=sticky", "", "", "boundaries.x_min"},
      {"zero output interval", "--set output.interval=0", "", "", "output.interval"},
      {"keep no checkpoint", "--set checkpoint.keep=0", "", "", "checkpoint.keep"},
      {"negative checkpoint interval", "--set checkpoint.every_steps=-5", "", "",
       "checkpoint.every_steps"},
      {"density band upside down", "--set checks.density_band=[2.0,0.5]", "", "",
       "checks.density_band"},
      {"step ratio above one", "--set checks.min_dt_ratio=2", "", "", "checks.min_dt_ratio"},
      {"XSPH eps above one", "--set scheme.xsph=2", "", "", "scheme.xsph"},
      {"negative alpha", "--set scheme.alpha=-1", "", "", "scheme.alpha"},
      {"override without =", "--set scheme.cfl", "", "", "scheme.cfl"},
      {"Morris's viscosity with CSPH", "--set scheme.preset=csph --set scheme.viscous_term=w57", "",
       "", "scheme.viscous_term"},
      {"Shepard filter on a summation density",
       "--set scheme.preset=standard --set scheme.shepard_every=5", "", "", "scheme.shepard_every"},
      {"unknown profile axis", "--set output.profile_axis=w", "", "", "output.profile_axis"},
      {"zero floor layer", "--set probes.floor_layer=0", "", "", "probes.floor_layer"},
      {"zero time scale", "--set validation.time_scale=0", "", "", "validation.time_scale"},
      {"a box that is not a box", "--set domain.max=[0.0,0.0]", "", "", "domain.max"},
      {"water outside the tank", "", "max = [0.05715, 0.05715]", "max = [0.5, 0.05715]",
       "fluid_blocks"},
      {"syntax: an unclosed table", "", "[particles]", "[particles", "TOML syntax error"},
      // The fuzzer's first finding: toml++ quotes the line break after a cut-short boolean.
      {"syntax: a boolean cut short", "", "surge_front = true", "surge_front = f",
       "TOML syntax error"},
      {"no case name", "", "name = \"small_dam_break\"", "", "case.name"},
      {"no water", "", "[[fluid_blocks]]\nmin = [0.0, 0.0]\nmax = [0.05715, 0.05715]", "",
       "fluid_blocks"},
      {"a vector of the wrong length", "", "min = [0.0, 0.0]\nmax = [0.2286",
       "min = [0.0, 0.0, 0.0]\nmax = [0.2286", "domain.min"},
  };
  return rows;
}

class MalformedInput : public test::FlumeBinaryTest {};

TEST_F(MalformedInput, EachGetsExitTwoAndOneLineNamingTheFileAndKey) {
  ASSERT_GE(malformed().size(), 30u);
  int k = 0;
  for (const auto& m : malformed()) {
    std::string toml = test::dam_break_toml("continuity", 8, 0.01);
    if (!m.replace.empty()) {
      const auto at = toml.find(m.replace);
      ASSERT_NE(at, std::string::npos) << m.what;
      toml.replace(at, m.replace.size(), m.with);
    }
    const auto file = dir_ / ("case_" + std::to_string(k) + ".toml");
    const auto out = dir_ / ("run_" + std::to_string(k++));
    std::ofstream(file) << toml;
    const auto r = flume("run " + file.string() + " " + m.args + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << m.what << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << m.what << ": " << r.err;
    EXPECT_NE(r.err.find(file.string()), std::string::npos) << m.what << ": " << r.err;
    EXPECT_NE(r.err.find(m.key), std::string::npos) << m.what << ": " << r.err;
    EXPECT_FALSE(fs::exists(out / "diagnostics.csv")) << m.what;
  }
}

}  // namespace
}  // namespace flume
