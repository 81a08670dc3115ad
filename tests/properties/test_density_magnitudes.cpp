// The magnitude of the density equations: summation BL (1), continuity BL (2)+(4), CSPH's
// corrected continuity (BL (2) with BL (55)) and the Shepard filter W (6.3). Hand-computed small
// cases (exact to round-off) and linear velocity fields on a lattice and a jittered cloud, whose
// exact divergence is known. Reached only through test::compute_rates / test::filter_density.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "flume/schemes/registry.hpp"
#include "support/hand_cases.hpp"
#include "support/lattice.hpp"
#include "support/rates.hpp"

namespace flume {
namespace {

constexpr double kRho0 = 1000.0, kDx = 0.01, kH = 1.3 * kDx;

Physics<2> water() {
  Physics<2> phys;
  phys.eos.rho0 = kRho0;
  phys.eos.kappa = 1e5;
  return phys;
}

std::unique_ptr<Scheme<2>> scheme(const std::string& preset, KernelKind kernel) {
  return make_scheme<2>(*preset_rows(preset), kernel, water());
}

// A sum of n terms of size `scale`, each exact to half an ulp, carries at most ~n ulp of `scale`:
// for these 3-term sums 1e-14 relative to the largest term's size is far above round-off and far
// below any wrong factor, weight or missing term.
constexpr double kHandTol = 1e-14;

TEST(DensityMagnitude, SummationBL1ByHandIncludesTheSelfTerm) {
  auto ps = test::triangle(kH);
  // Unequal smoothing lengths too: a pair uses h_ab = (h_a + h_b)/2 (W, text after (3.46)).
  ps.h[2] = 1.1 * kH;
  const auto before = ps;
  test::compute_rates(*scheme("standard", KernelKind::wendland_c2), ps);
  for (std::size_t a = 0; a < 3; ++a) {
    double rho = 0.0, scale = 0.0;
    for (std::size_t b = 0; b < 3; ++b) {
      const double h = 0.5 * (before.h[a] + before.h[b]);
      const double term = before.m[b] * test::wendland_w(norm(before.x[a] - before.x[b]), h);
      rho += term;  // b = a: the self term m_a W(0, h_a)
      scale = std::max(scale, term);
    }
    EXPECT_NEAR(ps.rho[a], rho, kHandTol * 3 * scale) << "particle " << a;
    // The self term alone is m_a W(0) = 0.1 * 7 / (4 pi h^2) ~ 330 kg/m^3 of the ~600: dropping it
    // moves rho by half, far outside the tolerance.
  }
}

class SummationLattice : public ::testing::TestWithParam<KernelKind> {};

TEST_P(SummationLattice, InteriorDensityIsTheKernelLatticeSum) {
  const KernelKind kernel = GetParam();
  const int n = 21;
  auto ps = test::square_lattice(
      n, kDx, kH, 0.0, 1, [](const Vec<2>&) { return kRho0; },
      [](const Vec<2>&) { return Vec<2>{}; });
  test::compute_rates(*scheme("standard", kernel), ps);
  const auto sums =
      with_kernel<2>(kernel, [](auto k) { return test::lattice_sums<decltype(k)>(kDx, kH); });
  // Every particle at least one support (3h for the quintic, 3.9 dx) from the edge has the full
  // lattice neighbourhood: rho = m sum_k W(|k| dx) = rho0 s0, up to the round-off of ~50 terms
  // (1e-13 relative).
  const auto interior = test::within(ps, (n / 2) * kDx - 4.0 * kDx);
  ASSERT_GE(interior.size(), 9u);
  for (const auto i : interior)
    EXPECT_NEAR(ps.rho[i], kRho0 * sums.s0, 1e-13 * kRho0) << kernel_name(kernel) << " " << i;
  // The kernel's lattice sum is its normalisation seen through the lattice: within 1 % of 1 at
  // h = 1.3 dx for all four kernels: s0 = 0.99995 (cubic), 0.99996 (quintic), 0.99997
  // (Gaussian), 1.0105 (Wendland C2), from the kernel formulas. So 1.5 % holds for every kernel,
  // while a wrong normalisation constant (a missing pi, another dimension's constant) is off by
  // tens of percent.
  EXPECT_NEAR(sums.s0, 1.0, 0.015) << kernel_name(kernel);
}

INSTANTIATE_TEST_SUITE_P(Kernels, SummationLattice, ::testing::ValuesIn(kernel_kinds),
                         [](const auto& p) { return std::string(kernel_name(p.param)); });

TEST(DensityMagnitude, ContinuityBL4ByHand) {
  auto ps = test::triangle(kH);
  const auto before = ps;
  test::compute_rates(*scheme("continuity", KernelKind::wendland_c2), ps);
  // BL (4): d rho_a/dt = -rho_a sum_b (m_b / rho_b) (v_b - v_a) . grad W_b(x_a); b = a adds 0.
  for (std::size_t a = 0; a < 3; ++a) {
    double div = 0.0, scale = 0.0;
    for (std::size_t b = 0; b < 3; ++b) {
      const double term =
          before.m[b] / before.rho[b] *
          dot(before.v[b] - before.v[a], test::wendland_grad(before.x[a], before.x[b], kH));
      div += term;
      scale = std::max(scale, std::abs(term));
    }
    EXPECT_NEAR(ps.drho[a], -before.rho[a] * div, kHandTol * 3 * before.rho[a] * scale) << a;
  }
}

// v = A x + v0 with a general A (stretching, shear, rotation): div v = tr A = 0.9 1/s.
Vec<2> linear_velocity(const Vec<2>& x) {
  return Vec<2>{{0.2 + 0.7 * x[0] - 1.3 * x[1], -0.5 + 2.1 * x[0] + 0.2 * x[1]}};
}
constexpr double kTraceA = 0.9;

TEST(DensityMagnitude, ContinuityBL4OfALinearFieldOnALattice) {
  for (const auto kernel : kernel_kinds) {
    const int n = 21;
    auto ps = test::square_lattice(
        n, kDx, kH, 0.0, 1, [](const Vec<2>&) { return kRho0; }, linear_velocity);
    test::compute_rates(*scheme("continuity", kernel), ps);
    const double c =
        with_kernel<2>(kernel, [](auto k) { return test::lattice_sums<decltype(k)>(kDx, kH).c; });
    // Interior (lattice module header): div v is exactly c tr A, so d rho/dt = -rho0 c tr A up
    // to round-off: terms of size V |A| h |grad W| ~ 1, 50 of them, against a result ~ 1e3:
    // 1e-12 relative is ample.
    for (const auto i : test::within(ps, (n / 2) * kDx - 4.0 * kDx)) {
      EXPECT_NEAR(ps.drho[i], -kRho0 * c * kTraceA, 1e-12 * kRho0 * kTraceA)
          << kernel_name(kernel) << " " << i;
      // And against the continuum -rho0 tr A: off by the lattice consistency error |c - 1| of
      // the uncorrected gradient (c = 1.0105 cubic, 1.0006 quintic, 0.9986 Gaussian, 0.9739
      // Wendland C2 at h = 1.3 dx, from the kernel formulas), so 3 % holds for every kernel and
      // a factor 1/2 or 2 is far outside.
      EXPECT_NEAR(ps.drho[i], -kRho0 * kTraceA, 0.03 * kRho0 * kTraceA) << kernel_name(kernel);
    }
  }
}

struct CloudError {
  double max = 0.0;   // max_i |drho_i / (-rho_i tr A) - 1| over the interior
  double mean = 0.0;  // mean of drho_i / (-rho_i tr A) - 1
};

CloudError continuity_error_on_jittered_cloud(const std::string& preset, double jitter, double c) {
  const int n = 25;
  auto ps = test::square_lattice(
      n, kDx, kH, jitter, 42, [](const Vec<2>&) { return kRho0; }, linear_velocity);
  test::compute_rates(*scheme(preset, KernelKind::cubic_spline), ps);
  CloudError e;
  const auto interior = test::within(ps, (n / 2) * kDx - 3.0 * kDx);
  for (const auto i : interior) {
    const double rel = ps.drho[i] / (-ps.rho[i] * c * kTraceA) - 1.0;
    e.max = std::max(e.max, std::abs(rel));
    e.mean += rel / static_cast<double>(interior.size());
  }
  return e;
}

TEST(DensityMagnitude, ContinuityBL4OfALinearFieldOnAJitteredCloud) {
  // Measured against the lattice value -rho c tr A (c = 1.0105, cubic spline, h = 1.3 dx), the
  // uncorrected divergence on a cloud jittered by up to j dx is off by the broken lattice
  // symmetry, which is first order in j: max error over the 361 interior particles 1.7 %, 4.2 %,
  // 8.3 %, 15.7 % at j = 0.02, 0.05, 0.1, 0.2 (0.84 j), while the mean error, where the first
  // order averages out, is second order (-0.04 %, -0.14 %, -0.37 %, -1.3 %). So: max < 11 % at
  // j = 0.1, halving j halves the max error (the same random pattern, scaled: ratio 1.98), and
  // the mean is within 1 %. Halving BL (4) puts both at 50 %.
  const double c = test::lattice_sums<CubicSpline<2>>(kDx, kH).c;
  const auto coarse = continuity_error_on_jittered_cloud("continuity", 0.1, c);
  const auto fine = continuity_error_on_jittered_cloud("continuity", 0.05, c);
  EXPECT_LT(coarse.max, 0.11);
  EXPECT_LT(std::abs(coarse.mean), 0.01);
  EXPECT_GT(coarse.max / fine.max, 1.8);
  EXPECT_LT(coarse.max / fine.max, 2.2);
}

TEST(DensityMagnitude, CsphContinuityOfALinearFieldIsExactOnAJitteredCloud) {
  // CSPH's rate, -rho_a sum_b V_b (v_b - v_a) . L_a grad W~_b(x_a) with L_a = M_a^{-T}, equals
  // -rho_a tr(A M_a^T M_a^{-T}) = -rho_a tr A exactly for a linear field on any cloud (BL (55),
  // (58)). Round-off: sums of ~30 terms of size |A| h times L ~ 1: 1e-12 relative to tr A.
  // A transposed L_a, an L_b for L_a or the uncorrected kernel gradient are off by the jitter's
  // first-order error, percent.
  const auto e = continuity_error_on_jittered_cloud("csph", 0.3, 1.0);
  EXPECT_LT(e.max, 1e-12);
}

TEST(DensityMagnitude, ShepardFilterW63ByHand) {
  auto ps = test::triangle(kH);
  const auto before = ps;
  test::filter_density(*scheme("continuity", KernelKind::wendland_c2), ps);
  // W (6.3): rho_a <- sum_b m_b W_ab / sum_b (m_b / rho_b) W_ab, self term included.
  for (std::size_t a = 0; a < 3; ++a) {
    double num = 0.0, den = 0.0;
    for (std::size_t b = 0; b < 3; ++b) {
      const double w = test::wendland_w(norm(before.x[a] - before.x[b]), kH);
      num += before.m[b] * w;
      den += before.m[b] / before.rho[b] * w;
    }
    // A quotient of two 3-term positive sums: a few ulp.
    EXPECT_NEAR(ps.rho[a], num / den, 1e-14 * num / den) << a;
    // Not a no-op: the three densities differ by up to 15 kg/m^3, the filtered ones by less.
    EXPECT_GT(std::abs(ps.rho[a] - before.rho[a]), 0.5) << a;
  }
  // Masses untouched.
  for (std::size_t a = 0; a < 3; ++a)
    EXPECT_EQ(ps.m[a], before.m[a]);
}

}  // namespace
}  // namespace flume
