// Two particles approaching each other must repel, for every preset: the sign-convention guard
// of spec/methods.md (erratum 1: with BL's tension-positive T_a and the compression-positive Tait
// EOS used as printed, compressed particles would attract).
#include <gtest/gtest.h>

#include "flume/schemes/registry.hpp"

namespace flume {
namespace {

struct Setup {
  ParticleSet<2> ps;
  Halo<2> halo;
  NeighborList nl;
};

// Particle 0 at the origin moving right, particle 1 at (0.8h, 0) moving left, both with mass
// m = rho0 h^2. The EOS reference density is set below their density (summation or given), so
// their pressure is positive: compressed fluid.
Setup two_particles(double rho) {
  Setup s;
  const double h = 1.0;
  s.ps.add_real(0, Vec<2>{{0.0, 0.0}}, Vec<2>{{1.0, 0.0}}, 1.0, rho, h);
  s.ps.add_real(1, Vec<2>{{0.8, 0.0}}, Vec<2>{{-1.0, 0.0}}, 1.0, rho, h);
  s.nl.offset = {0, 2, 4};
  s.nl.index = {0, 1, 0, 1};
  return s;
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
    auto s = two_particles(0.5);
    auto scheme = make_scheme<2>(rows, kernel, phys);
    scheme->compute_accelerations(s.ps, s.nl, s.halo);
    scheme->compute_density_rate(s.ps, s.nl, s.halo);
    ASSERT_GT(s.ps.p[0], 0.0) << "set-up must be in compression";
    EXPECT_LT(s.ps.a[0][0], 0.0) << GetParam() << " " << kernel_name(kernel)
                                 << ": particle 0 must be pushed away from particle 1";
    EXPECT_GT(s.ps.a[1][0], 0.0) << GetParam() << " " << kernel_name(kernel);
    // Equal masses: the pair force is antisymmetric, so the accelerations are opposite
    // (to round-off: 4 ulp of the magnitude).
    EXPECT_NEAR(s.ps.a[0][0], -s.ps.a[1][0], 4e-16 * std::abs(s.ps.a[0][0]));
    if (scheme->evolves_density()) {
      EXPECT_GT(s.ps.drho[0], 0.0) << "approaching particles compress: d rho/dt > 0";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, PairRepulsion,
                         ::testing::Values("standard", "continuity", "inconsistent", "csph"));

}  // namespace
}  // namespace flume
