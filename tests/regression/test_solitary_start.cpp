// A fluid block that starts as a KdV solitary wave already formed (fluid_blocks'
// solitary_amplitude, solitary_centre; theory/solitary_wave.hpp): its particles, their
// velocities and densities, and the bad input it can receive.
#include <gtest/gtest.h>

#include <cmath>

#include "flume/case/build_simulation.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

constexpr double kA = 0.03, kH = 0.15, kX0 = 1.5, kDx = 0.01, kG = 9.81;

std::string tank_toml(const std::string& block_extra) {
  return fmt::format(R"(
[case]
name = "solitary_start"
end_time = 0.01
[particles]
spacing = {dx}
[scheme]
preset = "wsph"
[domain]
min = [0.0, 0.0]
max = [4.0, 0.4]
[[fluid_blocks]]
min = [0.0, 0.0]
max = [4.0, {H}]
solitary_amplitude = {A}
solitary_centre = {x0}
{extra}
)",
                     fmt::arg("dx", kDx), fmt::arg("H", kH), fmt::arg("A", kA), fmt::arg("x0", kX0),
                     fmt::arg("extra", block_extra));
}

// eta = A sech^2((x - x0) / lambda), lambda = sqrt(4 H^3 / (3 A)) (W (6.15), (6.17)), written
// out here rather than taken from theory/solitary_wave.hpp.
double eta(double x) {
  const double lambda = std::sqrt(4.0 * kH * kH * kH / (3.0 * kA));
  const double c = std::cosh((x - kX0) / lambda);
  return kA / (c * c);
}
// u = V eta / (H + eta), V = sqrt(g H)(1 + A / (2 H)) (W (6.16)).
double u(double x) {
  const double v = std::sqrt(kG * kH) * (1.0 + kA / (2.0 * kH));
  return v * eta(x) / (kH + eta(x));
}

TEST(SolitaryStart, ParticlesFillTheKdvProfileAndMoveWithTheWave) {
  const auto spec = test::spec_from(tank_toml(""));
  const auto ps = build_particles<2>(spec, build_physics<2>(spec));
  // The lattice's cell centres below the surface, counted here column by column.
  long below = 0;
  for (int i = 0; i < 400; ++i) {
    const double x = (i + 0.5) * kDx;
    for (int j = 0; (j + 0.5) * kDx < kH + eta(x); ++j)
      ++below;
  }
  EXPECT_EQ(static_cast<long>(ps.n_real), below);
  double top = 0.0;
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    const double x = ps.x[i][0], z = ps.x[i][1];
    EXPECT_LT(z, kH + eta(x));
    top = std::max(top, z);
    // u from the formula; w = -z du/dx by a central difference of step 1e-6 m (truncation
    // ~1e-12 of u / lambda): 1e-8 m/s.
    EXPECT_NEAR(ps.v[i][0], u(x), 1e-14) << x;
    const double d = 1e-6;
    EXPECT_NEAR(ps.v[i][1], -z * (u(x + d) - u(x - d)) / (2.0 * d), 1e-8) << x << " " << z;
    // Hydrostatic under its own column: the densest particle of a column is at its foot.
    EXPECT_GE(ps.rho[i], 1000.0);
  }
  // The crest's column reaches within one spacing of H + A.
  EXPECT_GT(top, kH + kA - kDx);
  // A particle at the foot of the crest's column is denser than one at the foot of a column
  // far from the wave (hydrostatic under the taller column: rho0 g A / kappa more, to first
  // order; only the sign is asserted).
  double crest_foot = 0.0, far_foot = 0.0;
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    if (ps.x[i][1] > kDx) continue;
    if (std::abs(ps.x[i][0] - kX0) < kDx) crest_foot = ps.rho[i];
    if (ps.x[i][0] < kDx) far_foot = ps.rho[i];
  }
  EXPECT_GT(crest_foot, far_foot);
}

TEST(SolitaryStart, TowardXMinIsTheMirrorImage) {
  // The same particles (the profile is even about x0), every velocity negated: both components
  // of the mirror image of the wave travelling toward x_max (checked above), so the wave
  // travels toward x_min.
  const auto east = test::spec_from(tank_toml(""));
  const auto west = test::spec_from(tank_toml("solitary_towards = \"x_min\""));
  const auto a = build_particles<2>(east, build_physics<2>(east));
  const auto b = build_particles<2>(west, build_physics<2>(west));
  ASSERT_EQ(a.n_real, b.n_real);
  double fastest = 0.0;
  for (std::size_t i = 0; i < a.n_real; ++i) {
    EXPECT_EQ(a.x[i], b.x[i]);
    EXPECT_EQ(b.v[i][0], -a.v[i][0]);
    EXPECT_EQ(b.v[i][1], -a.v[i][1]);
    fastest = std::min(fastest, b.v[i][0]);
  }
  EXPECT_LT(fastest, -0.1);  // V A / (H + A) = 0.24 m/s at the crest, toward -x
}

TEST(SolitaryStart, MoundLatticeReachesItsCrest) {
  // W (6.21)'s mound y = H + B exp(-k x) (B = 0.07, k = 2.5, H = 0.15) at 0.025 m: the box's
  // 6 rows and 3 more, cut by the surface. Counted here column by column: 2 particles more than
  // rows counted from the floor of (H + B) / dx (8) allowed, the crest's 9th row.
  const auto spec = test::spec_from(
      tank_toml(""),
      {"particles.spacing=0.025", "fluid_blocks[0].solitary_amplitude=0.0",
       "fluid_blocks[0].surface_amplitude=0.07", "fluid_blocks[0].surface_decay=2.5"});
  const auto ps = build_particles<2>(spec, build_physics<2>(spec));
  const double dx = 0.025;
  long below = 0;
  double crest = 0.0;
  for (int i = 0; i < 160; ++i) {
    const double x = (i + 0.5) * dx, top = kH + 0.07 * std::exp(-2.5 * x);
    for (int j = 0; (j + 0.5) * dx < top; ++j) {
      ++below;
      crest = std::max(crest, (j + 0.5) * dx);
    }
  }
  EXPECT_EQ(static_cast<long>(ps.n_real), below);
  double highest = 0.0;
  for (std::size_t i = 0; i < ps.n_real; ++i)
    highest = std::max(highest, ps.x[i][1]);
  EXPECT_EQ(highest, crest);  // 8.5 dx = 0.2125 m, below the crest at 0.22 m
  EXPECT_NEAR(highest, 0.2125, 1e-12);
}

TEST(SolitaryStart, BadWavesAreOneLineErrors) {
  using test::error_of;
  using test::expect_one_line_with;
  // W (6.18): A / H < 0.78.
  expect_one_line_with(error_of(tank_toml(""), {"fluid_blocks[0].solitary_amplitude=0.12"}),
                       {"fluid_blocks[0].solitary_amplitude", "0.78 H", "W (6.18)"});
  expect_one_line_with(error_of(tank_toml("surface_amplitude = 0.05\nsurface_decay = 2.5")),
                       {"fluid_blocks[0].solitary_amplitude", "surface_amplitude"});
  expect_one_line_with(error_of(tank_toml(""), {"fluid_blocks[0].solitary_centre=5.0"}),
                       {"fluid_blocks[0].solitary_centre", "within the block"});
  expect_one_line_with(error_of(tank_toml(""), {"fluid_blocks[0].solitary_amplitude=-0.01"}),
                       {"fluid_blocks[0].solitary_amplitude"});
  expect_one_line_with(error_of(tank_toml("solitary_towards = \"up\"")),
                       {"fluid_blocks[0].solitary_towards", "x_max, x_min"});
  expect_one_line_with(error_of(tank_toml(""), {"domain.max=[4.0, 0.17]"}),
                       {"fluid_blocks[0].solitary_amplitude", "above the domain's top"});
}

}  // namespace
}  // namespace flume
