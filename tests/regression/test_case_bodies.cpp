// Fluid bodies of a case file beyond the lattice box (the elliptical drop of BL 5.2): an
// ellipsoid inscribed in the block, random layouts from a seed, a linear initial velocity
// field; the correction row; and the bad input each can receive.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flume/case/build_simulation.hpp"
#include "flume/core/error.hpp"
#include "flume/io/csv_table.hpp"
#include "flume/validation/theory_reference.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

std::string drop_toml(const std::string& block_extra, const std::string& more = "") {
  return R"(
[case]
name = "drop"
end_time = 0.008
[particles]
spacing = 0.051511
[scheme]
preset = "csph"
[fluid]
gravity = [0.0, 0.0]
[eos]
bulk_modulus = 285.714e6
[domain]
min = [-4.0, -4.0]
max = [4.0, 4.0]
[boundaries]
x_min = "open"
x_max = "open"
y_min = "open"
y_max = "open"
[[fluid_blocks]]
min = [-1.0, -1.0]
max = [1.0, 1.0]
shape = "ellipsoid"
velocity_gradient = [-100.0, 0.0, 0.0, 100.0]
hydrostatic = false
)" + block_extra +
         "\n" + more;
}

using test::error_of;

// The drop's semi-axis b compared with the exact solution computed by flume.
constexpr const char* kSemiAxisCurve = R"(
[[validation.curves]]
probe = "semi_axis_y"
reference = "theory:elliptical_drop"
reference_x = "t"
reference_y = "b"
)";

TEST(CaseBodies, EllipsoidLatticeIsCentredAndCarriesTheVelocityField) {
  const auto spec = test::spec_from(drop_toml(""));
  const auto ps = build_particles<2>(spec, build_physics<2>(spec));
  // The cell centres of spacing dx inside the unit circle: about pi / dx^2 = 1184 of them
  // (1176 for this spacing, counted independently below).
  long inside = 0;
  const double dx = 0.051511;
  const int n = static_cast<int>(std::floor(2.0 / dx + 1e-6));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5 - 0.5 * n) * dx, y = (j + 0.5 - 0.5 * n) * dx;
      inside += x * x + y * y <= 1.0;
    }
  EXPECT_EQ(static_cast<long>(ps.n_real), inside);
  Vec<2> centre, momentum;
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    EXPECT_LE(norm(ps.x[i]), 1.0);
    // v = G x with G = diag(-100, 100), exactly.
    EXPECT_EQ(ps.v[i][0], -100.0 * ps.x[i][0]);
    EXPECT_EQ(ps.v[i][1], 100.0 * ps.x[i][1]);
    EXPECT_DOUBLE_EQ(ps.m[i], 1000.0 * dx * dx);
    centre += ps.x[i];
    momentum += ps.v[i] * ps.m[i];
  }
  // Symmetric about the origin: no net momentum (round-off of ~1e3 terms of size ~1e3).
  EXPECT_LT(norm(centre), 1e-12 * static_cast<double>(ps.n_real));
  EXPECT_LT(norm(momentum), 1e-9);
}

TEST(CaseBodies, RandomLayoutIsRepeatableCentredAndKeepsItsMinimumDistance) {
  const std::string extra = "layout = \"random\"\ncount = 500\nseed = 7\nmin_distance = 0.7";
  const auto spec = test::spec_from(drop_toml(extra));
  const auto a = build_particles<2>(spec, build_physics<2>(spec));
  const auto b = build_particles<2>(spec, build_physics<2>(spec));
  ASSERT_EQ(a.n_real, 500u);
  Vec<2> centre;
  double closest = 1e9;
  for (std::size_t i = 0; i < a.n_real; ++i) {
    EXPECT_EQ(a.x[i], b.x[i]);  // the same seed, the same cloud
    // Equal masses: rho0 times the circle's area over the count.
    EXPECT_DOUBLE_EQ(a.m[i], 1000.0 * std::numbers::pi / 500.0);
    centre += a.x[i];
    for (std::size_t j = 0; j < i; ++j)
      closest = std::min(closest, norm(a.x[i] - a.x[j]));
  }
  EXPECT_LT(norm(centre) / 500.0, 1e-15);  // moved so that its centre of mass is the origin
  EXPECT_GE(closest, 0.7 * 0.051511 * (1.0 - 1e-12));
  const auto other = test::spec_from(drop_toml(extra), {"fluid_blocks[0].seed=8"});
  const auto c = build_particles<2>(other, build_physics<2>(other));
  EXPECT_NE(a.x[0], c.x[0]);
}

TEST(CaseBodies, BadBodiesAreOneLineErrors) {
  for (const auto& [extra, parts] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"layout = \"random\"", {"fluid_blocks[0].count", "1 to 1e8"}},
           {"count = 10", {"fluid_blocks[0].count", "random"}},
           {"shape = \"sphere\"", {"fluid_blocks[0].shape", "box, ellipsoid"}},
           {"layout = \"random\"\ncount = 10\nmin_distance = 2.0", {"min_distance", "[0, 1]"}},
           {"layout = \"random\"\ncount = 10\nseed = -1", {"fluid_blocks[0].seed", ">= 0"}},
       }) {
    std::string toml = drop_toml("");
    toml.replace(toml.find("shape = \"ellipsoid\""), 19,
                 extra.find("shape") == 0 ? extra : "shape = \"ellipsoid\"\n" + extra);
    const std::string msg = error_of(toml);
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    for (const auto& p : parts)
      EXPECT_NE(msg.find(p), std::string::npos) << p << " in: " << msg;
  }
  // A velocity gradient of the wrong size.
  std::string toml = drop_toml("");
  toml.replace(toml.find("[-100.0, 0.0, 0.0, 100.0]"), 25, "[-100.0, 100.0]");
  EXPECT_NE(error_of(toml).find("4 numbers (a 2 x 2 matrix"), std::string::npos) << error_of(toml);
  // A curve of a probe the case does not measure, and an unknown theory.
  const std::string curve = kSemiAxisCurve;
  EXPECT_NE(error_of(drop_toml("", curve)).find("do not measure it"), std::string::npos);
  std::string unknown = curve;
  unknown.replace(unknown.find("elliptical_drop"), 15, "dam_break");
  const std::string unknown_msg = error_of(drop_toml("", "[probes]\nsemi_axes = true\n" + unknown));
  EXPECT_NE(unknown_msg.find("theory:elliptical_drop"), std::string::npos) << unknown_msg;
  EXPECT_NE(unknown_msg.find("theory:bore"), std::string::npos) << unknown_msg;
  // A correction without a scheme for the density and force.
  const std::string msg = error_of(drop_toml(""), {"scheme.correction=first_order"});
  EXPECT_NE(msg.find("scheme.correction"), std::string::npos) << msg;
  EXPECT_NE(msg.find("continuity+bl59+mixed"), std::string::npos) << msg;
}

TEST(CaseBodies, TheoryReferenceIsTheExactDropSolution) {
  const std::string curve = std::string("[probes]\nsemi_axes = true\n") + kSemiAxisCurve;
  const auto spec = test::spec_from(drop_toml("", curve));
  const auto ref = curve_reference(spec, spec.curves.front(), {});
  const auto t = ref.column("t"), a = ref.column("a"), b = ref.column("b");
  ASSERT_EQ(t.size(), 40u);
  EXPECT_DOUBLE_EQ(t.back(), 0.008);
  // cases.md BL-1: b = 1.9993 at 0.008 s (half a unit of the last digit), a b = 1.
  EXPECT_NEAR(b.back(), 1.9993, 5e-5);
  for (std::size_t k = 0; k < t.size(); ++k)
    EXPECT_NEAR(a[k] * b[k], 1.0, 1e-12);
  // A drop that does not fit the solution (not a circle) is refused, naming the reference.
  std::string oval = drop_toml("", curve);
  oval.replace(oval.find("max = [1.0, 1.0]"), 16, "max = [1.0, 1.5]");
  const auto bad = test::spec_from(oval);
  EXPECT_THROW(curve_reference(bad, bad.curves.front(), {}), InputError);
}

}  // namespace
}  // namespace flume
