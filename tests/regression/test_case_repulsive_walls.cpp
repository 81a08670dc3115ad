// [[repulsive_walls]] and the beach probes in a case file: the fluid blocks are cut by the
// walls, the defaults resolve, and bad input is one line naming the key.
#include <gtest/gtest.h>

#include <cmath>

#include "flume/case/build_simulation.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

std::string beach_toml(const std::string& wall_extra = "", const std::string& more = "") {
  return R"(
[case]
name = "beach"
end_time = 0.1
[particles]
spacing = 0.02
[scheme]
preset = "wsph"
[fluid]
gravity = [0.0, -9.81]
[domain]
min = [0.0, 0.0]
max = [2.0, 0.5]
[[fluid_blocks]]
min = [0.0, 0.0]
max = [2.0, 0.2]
[[repulsive_walls]]
from = [1.0, 0.0]
to = [2.0, 0.4]
)" + wall_extra +
         "\n" + more;
}

using test::error_of;

TEST(CaseRepulsiveWalls, BlocksAreCutAtTheWallsReachAndDefaultsResolve) {
  const auto spec = test::spec_from(beach_toml());
  ASSERT_EQ(spec.repulsive_walls.size(), 1u);
  const auto& w = spec.repulsive_walls[0];
  EXPECT_EQ(w.force, "monaghan_kos");
  EXPECT_DOUBLE_EQ(w.spacing, 0.02);                // particles.spacing
  EXPECT_DOUBLE_EQ(w.put_back_distance, 0.01);      // half a spacing
  EXPECT_DOUBLE_EQ(w.clearance, 2.0 * 1.3 * 0.02);  // 2h, Monaghan-Kos's reach
  EXPECT_DOUBLE_EQ(w.strength, 5.0 * 9.81 * 0.2);   // 5 g H for Lennard-Jones
  EXPECT_DOUBLE_EQ(w.cutoff, 0.02);
  const auto sim = build_simulation<2>(spec);
  const auto& ps = sim.particles();
  // The lattice holds 100 x 10 cells; those in front of the beach's length and within 2h of
  // it, or behind it, are empty.
  const double n_len = std::sqrt(1.0 + 0.16);
  std::size_t kept = 0;
  for (int c = 0; c < 100; ++c)
    for (int r = 0; r < 10; ++r) {
      const double x = (c + 0.5) * 0.02, y = (r + 0.5) * 0.02;
      const double d = (-(x - 1.0) * 0.4 + y) / n_len;       // in front of the beach, m
      const double s = ((x - 1.0) + 0.4 * y) / n_len;        // along it from the toe, m
      if (s < 0.0 || s > n_len || d >= w.clearance) ++kept;  // beside it, or clear of it
    }
  EXPECT_EQ(ps.n_real, kept);
  for (std::size_t i = 0; i < ps.n_real; ++i)
    if (ps.x[i][0] > 1.0) {
      EXPECT_GE((-(ps.x[i][0] - 1.0) * 0.4 + ps.x[i][1]) / n_len, w.clearance - 1e-12);
    }
}

TEST(CaseRepulsiveWalls, BadWallsAreOneLineErrors) {
  for (const auto& [extra, parts] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"force = \"spring\"", {"repulsive_walls[0].force", "monaghan_kos, lennard_jones"}},
           {"powers = [4.0, 12.0]", {"repulsive_walls[0].powers", "p1 > p2"}},
           {"stroke = 0.2", {"repulsive_walls[0].frequency", "paddle"}},
           {"stroke = 2.0\nfrequency = 1.0", {"repulsive_walls[0].stroke", "out of the domain"}},
           {"spacing = 0.8", {"repulsive_walls[0].spacing", "smaller spacing"}},
           {"put_back_distance = 3.0", {"repulsive_walls[0].put_back_distance"}},
           // A backstop that cannot push (found laying one along a mirror floor, stop 31).
           {"reach = 0.5", {"repulsive_walls[0].reach", "put_back_distance", "never push"}},
       }) {
    const std::string msg = error_of(beach_toml(extra));
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    for (const auto& p : parts)
      EXPECT_NE(msg.find(p), std::string::npos) << p << " in: " << msg;
  }
  std::string same = beach_toml();
  same.replace(same.find("to = [2.0, 0.4]"), 15, "to = [1.0, 0.0]");
  test::expect_one_line_with(error_of(same), {"repulsive_walls[0].to", "differ"});
  std::string outside = beach_toml();
  outside.replace(outside.find("to = [2.0, 0.4]"), 15, "to = [2.5, 0.4]");
  test::expect_one_line_with(error_of(outside), {"repulsive_walls[0].to", "domain box"});
  test::expect_one_line_with(error_of(beach_toml("", "[probes]\nbeach_slope = 0.4\n")),
                             {"probes.beach_slope", "waves"});
  test::expect_one_line_with(
      error_of(beach_toml("", "[probes]\nwaves = true\nbeach_slope = 0.4\nbeach_toe = 3.0\n")),
      {"probes.beach_toe", "inside the domain"});
  test::expect_one_line_with(error_of(beach_toml("", "[probes]\nbed_span = [0.5, 0.2]\n")),
                             {"probes.bed_span", "x_lo < x_hi"});
  test::expect_one_line_with(
      error_of(beach_toml(), {"eos.kind=ideal_gas", "fluid_blocks[0].hydrostatic=false",
                              "fluid_blocks[0].internal_energy=1.0"}),
      {"repulsive_walls[0]", "tait"});
}

}  // namespace
}  // namespace flume
