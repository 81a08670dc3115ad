// Two particles approaching each other must repel, for every preset: the sign-convention guard
// of spec/methods.md (erratum 1: with BL's tension-positive T_a and the compression-positive Tait
// EOS used as printed, compressed particles would attract).
#include <gtest/gtest.h>

#include "flume/schemes/registry.hpp"
#include "support/rates.hpp"

namespace flume {
namespace {

// Particle 0 at the origin moving right, particle 1 at (0.8h, 0) moving left, both with mass
// m = rho0 h^2. The EOS reference density is set below their density (summation or given), so
// their pressure is positive: compressed fluid.
ParticleSet<2> two_particles(double rho) {
  ParticleSet<2> ps;
  const double h = 1.0;
  ps.add_real(0, Vec<2>{{0.0, 0.0}}, Vec<2>{{1.0, 0.0}}, 1.0, rho, h);
  ps.add_real(1, Vec<2>{{0.8, 0.0}}, Vec<2>{{-1.0, 0.0}}, 1.0, rho, h);
  return ps;
}

class PairRepulsion : public ::testing::TestWithParam<std::string> {};

TEST_P(PairRepulsion, ApproachingParticlesRepel) {
  const auto rows = *preset_rows(GetParam());
  Physics<2> phys;
  // Two unit masses at 0.8 h: the summed density is W(0) + W(0.8 h) ~ 0.62 /m^2, so a reference
  // density of 0.1 puts both presets in compression.
  phys.eos.rho0 = 0.1;
  phys.eos.kappa = 1.0;
  phys.mu = 0.01;
  phys.av_alpha = 0.1;
  for (const auto kernel : kernel_kinds) {
    auto ps = two_particles(0.5);
    auto scheme = make_scheme<2>(rows, kernel, phys);
    test::compute_rates(*scheme, ps);
    ASSERT_GT(ps.p[0], 0.0) << "set-up must be in compression";
    EXPECT_LT(ps.a[0][0], 0.0) << GetParam() << " " << kernel_name(kernel)
                               << ": particle 0 must be pushed away from particle 1";
    EXPECT_GT(ps.a[1][0], 0.0) << GetParam() << " " << kernel_name(kernel);
    // Equal masses: the pair force is antisymmetric, so the accelerations are opposite
    // (to round-off: 4 ulp of the magnitude).
    EXPECT_NEAR(ps.a[0][0], -ps.a[1][0], 4e-16 * std::abs(ps.a[0][0]));
    if (scheme->evolves_density()) {
      EXPECT_GT(ps.drho[0], 0.0) << "approaching particles compress: d rho/dt > 0";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, PairRepulsion,
                         ::testing::Values("standard", "continuity", "inconsistent", "csph"));

}  // namespace
}  // namespace flume
