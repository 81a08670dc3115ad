// Unit tests of the bore reference solution (src/flume/theory/bore.hpp), BL
// section 5.4: BL (67) v_s = -v0 + sqrt(g h (1 + h/h0) / 2) and BL (68) h/h0 =
// (v_s + v0)/v_s.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "flume/theory/bore.hpp"

namespace flume {
namespace {

constexpr double kG = 9.81;  // m/s^2
constexpr double kH0 = 0.1;  // m, the BL-3 layer depth

// Relative residuals of BL (67) and BL (68) for a returned pair.
double residual_67(const BoreSolution& s, double h0, double v0, double g) {
  const double rhs = -v0 + std::sqrt(0.5 * g * s.h * (1.0 + s.h / h0));
  return std::abs(s.v_s - rhs) / (s.v_s + v0);
}
double residual_68(const BoreSolution& s, double h0, double v0) {
  return std::abs(s.h / h0 - (s.v_s + v0) / s.v_s) / (s.h / h0);
}

TEST(BoreTheory, MatchesReferenceValues) {
  // cases.md BL-3 (g = 9.81, h0 = 0.1 m), printed to 4 decimals: the tolerance
  // is half a unit of the last printed digit, 0.5e-4 (m for h, m/s for v_s).
  const BoreSolution fr09 = bore_solution(kH0, 0.8914, kG);
  EXPECT_NEAR(fr09.h, 0.2043, 0.5e-4);
  EXPECT_NEAR(fr09.v_s, 0.8548, 0.5e-4);
  const BoreSolution fr03 = bore_solution(kH0, 0.2971, kG);
  EXPECT_NEAR(fr03.h, 0.1320, 0.5e-4);
  EXPECT_NEAR(fr03.v_s, 0.9285, 0.5e-4);
}

TEST(BoreTheory, FroudeNumbersOfTheCases) {
  // Fr = v0 / sqrt(g h0): the two speeds of cases.md are Froude 0.9 and 0.3 to
  // 4 decimals.
  EXPECT_NEAR(bore_froude(kH0, 0.8914, kG), 0.9, 0.5e-4);
  EXPECT_NEAR(bore_froude(kH0, 0.2971, kG), 0.3, 0.5e-4);
}

TEST(BoreTheory, SatisfiesBothEquations) {
  // The returned pair satisfies BL (67) and BL (68) to round-off, from a barely
  // moving layer to a strongly supercritical one.
  for (const double fr : {1e-3, 0.05, 0.3, 0.9, 1.0, 2.0, 5.0, 20.0}) {
    for (const double h0 : {0.01, 0.1, 2.0}) {
      const double v0 = fr * std::sqrt(kG * h0);
      const BoreSolution s = bore_solution(h0, v0, kG);
      EXPECT_LE(residual_67(s, h0, v0, kG), 1e-12) << "Fr " << fr << " h0 " << h0;
      EXPECT_LE(residual_68(s, h0, v0), 1e-12) << "Fr " << fr << " h0 " << h0;
    }
  }
}

TEST(BoreTheory, FroudeSimilarity) {
  // Only g, h0 and v0 enter, so at fixed Froude h/h0 and v_s/sqrt(g h0) are the
  // same for any depth and gravity.
  const double fr = 0.9;
  const BoreSolution ref = bore_solution(kH0, fr * std::sqrt(kG * kH0), kG);
  for (const double h0 : {0.003, 0.5, 40.0}) {
    for (const double g : {1.62, 9.81, 24.8}) {
      const BoreSolution s = bore_solution(h0, fr * std::sqrt(g * h0), g);
      EXPECT_NEAR(s.h / h0, ref.h / kH0, 1e-13 * ref.h / kH0) << "h0 " << h0 << " g " << g;
      EXPECT_NEAR(s.v_s / std::sqrt(g * h0), ref.v_s / std::sqrt(kG * kH0), 1e-13)
          << "h0 " << h0 << " g " << g;
    }
  }
}

TEST(BoreTheory, PhysicalSanity) {
  // The water piles up (h > h0) and the bore runs away from the wall (v_s > 0);
  // a faster layer gives a higher bore. As v0 -> 0 the jump vanishes and the
  // bore becomes a small wave, v_s -> sqrt(g h0) (BL (67) at h = h0).
  double h_prev = kH0;
  for (const double v0 : {1e-6, 0.01, 0.1, 0.2971, 0.8914, 2.0}) {
    const BoreSolution s = bore_solution(kH0, v0, kG);
    EXPECT_GT(s.h, h_prev) << "v0 " << v0;
    EXPECT_GT(s.v_s, 0.0) << "v0 " << v0;
    h_prev = s.h;
  }
  const BoreSolution tiny = bore_solution(kH0, 1e-9, kG);
  EXPECT_NEAR(tiny.h, kH0, 1e-8);
  EXPECT_NEAR(tiny.v_s, std::sqrt(kG * kH0), 1e-8);
  const BoreSolution still = bore_solution(kH0, 0.0, kG);
  EXPECT_EQ(still.h, kH0);
  EXPECT_EQ(still.v_s, std::sqrt(kG * kH0));
}

TEST(BoreTheory, RejectsBadInput) {
  EXPECT_THROW(bore_solution(0.0, 0.5, kG), std::invalid_argument);
  EXPECT_THROW(bore_solution(kH0, -0.5, kG), std::invalid_argument);
  EXPECT_THROW(bore_solution(kH0, 0.5, 0.0), std::invalid_argument);
  EXPECT_THROW(bore_solution(kH0, std::numeric_limits<double>::infinity(), kG),
               std::invalid_argument);
}

}  // namespace
}  // namespace flume
