// The equations that declare kGradientOnly (own.hpp) have their self pair skipped by the sweep.
// That is only right if their self pair (r = 0, grad W = 0, W = W(0) > 0) adds exact zeros to
// both shares, whatever the particle's fields: checked here for each of them with generic,
// nonzero fields, so that a term carrying W (or a constant) in such an equation is caught.
#include <gtest/gtest.h>

#include <cstring>

#include "flume/equations/acceleration_sum.hpp"
#include "flume/equations/continuity_density_bl4.hpp"
#include "flume/equations/density_rate_euler_w350.hpp"
#include "flume/equations/density_rate_weak_w379.hpp"
#include "flume/equations/density_summation.hpp"
#include "flume/equations/energy_euler_w352.hpp"
#include "flume/equations/energy_weak_w381.hpp"
#include "flume/equations/force_bonet_lok_20.hpp"
#include "flume/equations/force_bonet_lok_7.hpp"
#include "flume/equations/force_weak_w380.hpp"
#include "flume/equations/own.hpp"
#include "flume/equations/velocity_gradient_bl22.hpp"
#include "flume/equations/viscosity_artificial_monaghan.hpp"
#include "flume/equations/viscosity_bonet_lok_24.hpp"

namespace flume {
namespace {

// One particle with every field set to something nonzero and unremarkable.
ParticleSet<2> one_particle() {
  ParticleSet<2> ps;
  ps.add_real(7, Vec<2>{{0.1, 0.2}}, Vec<2>{{0.3, -0.7}}, 0.011, 1013.0, 0.013);
  ps.p[0] = 2.5e3;
  ps.c[0] = 21.0;
  ps.grad_v[0] = Mat<2>{{0.4, -1.1, 2.0, 0.3}};
  ps.stress[0] = Mat<2>{{1e-3, 2e-3, 2e-3, -1e-3}};
  ps.e[0] = 1.7;
  ps.L[0] = Mat<2>{{1.1, 0.2, -0.1, 0.9}};
  return ps;
}

// The self pair as the sweep would hand it over.
Pair<2> self_pair(const ParticleSet<2>& ps) {
  Pair<2> g;
  g.h = ps.h[0];
  g.w = 7.0 / (4.0 * 3.141592653589793) / (g.h * g.h);  // Wendland C2's W(0): any W > 0 will do
  return g;
}

template <class Eq>
void expect_zero_self_pair(const Eq& eq, const ParticleSet<2>& ps, const char* name) {
  static_assert(gradient_only<Eq>(), "only for equations that declare kGradientOnly");
  typename Eq::Acc ai = eq.init(0), aj = eq.init(0);
  const auto before_i = ai;
  pair_of(eq, ai, aj, own_of(eq, 0), own_of(eq, 0), 0, 0, self_pair(ps));
  // Exact: every term is a product with grad W = 0 (a share of zeros).
  EXPECT_EQ(std::memcmp(&ai, &before_i, sizeof ai), 0) << name << ": i's share";
  EXPECT_EQ(std::memcmp(&aj, &before_i, sizeof aj), 0) << name << ": j's share";
}

TEST(SelfPair, GradientOnlyEquationsAddExactZeros) {
  auto ps = one_particle();
  ForceBonetLok7<2> bl7{ps};
  ForceBonetLok20<2> bl20{ps};
  ViscosityBonetLok24<2> bl24{ps};
  ViscosityArtificialMonaghan<2> av{ps, 1.0, 2.0};
  ContinuityDensityBL4<2> bl4{ps, ps.v};
  VelocityGradientBL22<2> bl22{ps};
  expect_zero_self_pair(bl7, ps, "BL (7)");
  expect_zero_self_pair(bl20, ps, "BL (20)");
  expect_zero_self_pair(bl24, ps, "BL (24)");
  expect_zero_self_pair(av, ps, "W (3.18)");
  expect_zero_self_pair(bl4, ps, "BL (4)");
  expect_zero_self_pair(bl22, ps, "BL (22)");
  AccelerationSum<2, ForceBonetLok7<2>, ViscosityArtificialMonaghan<2>> sum{ps, Vec<2>{}, bl7, av};
  expect_zero_self_pair(sum, ps, "AccelerationSum");
  // The thesis's equations, gas (q = p) and liquid (q = 1), plain and renormalized.
  for (const bool gas : {true, false}) {
    expect_zero_self_pair(DensityRateEulerW350<2>{ps, ps.v, gas}, ps, "W (3.50)");
    expect_zero_self_pair(DensityRateWeakW379<2>{ps, ps.v, gas}, ps, "W (3.79)");
    expect_zero_self_pair(DensityRateWeakW379<2, RenormalizedGradient>{ps, ps.v, gas}, ps,
                          "W (4.19)");
  }
  expect_zero_self_pair(EnergyEulerW352<2>{ps, ps.v, 1.0, 2.0}, ps, "W (3.52)");
  expect_zero_self_pair(ForceWeakW380<2>{ps, 1.0, 2.0}, ps, "W (3.80)");
  expect_zero_self_pair(ForceWeakW380<2, RenormalizedGradient>{ps, 1.0, 2.0}, ps, "W (4.20)");
  expect_zero_self_pair(EnergyWeakW381<2>{ps, ps.v, 1.0, 2.0}, ps, "W (3.81)");
  expect_zero_self_pair(EnergyWeakW381<2, RenormalizedGradient>{ps, ps.v, 1.0, 2.0}, ps,
                        "W (4.21)");
}

TEST(SelfPair, EquationsWithAWTermKeepTheirSelfPair) {
  // The summation density's self term m_a W(0) is its largest: it must not declare the trait,
  // and a sum with any such term must not either.
  static_assert(!gradient_only<DensitySummation<2>>());
  auto ps = one_particle();
  DensitySummation<2> density{ps};
  double ai = 0.0, aj = 0.0;
  density.pair(ai, aj, 0, 0, self_pair(ps));
  EXPECT_GT(ai, 0.0);
}

}  // namespace
}  // namespace flume
