// Unit tests of the smallest singular value (src/flume/core/singular_value.hpp), the criterion of
// the correction matrices: matrices built as U diag(s) V^T from rotations U, V and chosen
// singular values s, so the answer is known independently of the eigenvalue route.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "flume/core/singular_value.hpp"

namespace flume {
namespace {

Mat<2> rotation2(double t) {
  Mat<2> r;
  r(0, 0) = std::cos(t);
  r(0, 1) = -std::sin(t);
  r(1, 0) = std::sin(t);
  r(1, 1) = std::cos(t);
  return r;
}

// A rotation about a random axis by a random angle (Rodrigues).
Mat<3> rotation3(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec<3> k{{n(rng), n(rng), n(rng)}};
  k = k * (1.0 / norm(k));
  const double t = 3.0 * n(rng);
  Mat<3> K;
  K(0, 1) = -k[2];
  K(0, 2) = k[1];
  K(1, 0) = k[2];
  K(1, 2) = -k[0];
  K(2, 0) = -k[1];
  K(2, 1) = k[0];
  return Mat<3>::identity() + K * std::sin(t) + K * K * (1.0 - std::cos(t));
}

// Round-off: sigma_min^2 is an eigenvalue of M^T M (entries ~1, errors ~1e-16) found in closed
// form; near a double eigenvalue the trigonometric route loses about half the digits of the
// squared value, so the smallest value is good to ~1e-8 absolute in the worst case and far
// better otherwise. 1e-7 absolute is far below any threshold use (0.05) and a wrong branch of
// the cubic or of the quadratic gives O(1) errors.
TEST(SingularValue, SmallestOfKnownMatrices2D) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 2.0), angle(-3.2, 3.2);
  for (int trial = 0; trial < 1000; ++trial) {
    const double s0 = u(rng), s1 = u(rng);
    Mat<2> S;
    S(0, 0) = s0;
    S(1, 1) = s1;
    const Mat<2> M = rotation2(angle(rng)) * S * transpose(rotation2(angle(rng)));
    EXPECT_NEAR(smallest_singular_value(M), std::min(s0, s1), 1e-7) << trial;
  }
}

TEST(SingularValue, SmallestOfKnownMatrices3D) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.0, 2.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const double s[3] = {u(rng), u(rng), u(rng)};
    Mat<3> S;
    for (int k = 0; k < 3; ++k)
      S(k, k) = s[k];
    const Mat<3> M = rotation3(rng) * S * transpose(rotation3(rng));
    EXPECT_NEAR(smallest_singular_value(M), std::min({s[0], s[1], s[2]}), 1e-7) << trial;
  }
}

TEST(SingularValue, SingularAndIdentityMatrices) {
  // Rank one: the outer product of two vectors has sigma_min 0 (to round-off).
  EXPECT_NEAR(smallest_singular_value(outer(Vec<2>{{1.0, 2.0}}, Vec<2>{{-0.5, 3.0}})), 0.0, 1e-7);
  EXPECT_NEAR(smallest_singular_value(outer(Vec<3>{{1.0, 2.0, 0.5}}, Vec<3>{{-0.5, 3.0, 1.0}})),
              0.0, 1e-7);
  EXPECT_DOUBLE_EQ(smallest_singular_value(Mat<3>::identity() * 0.5), 0.5);
  // A shear keeps det = 1 but is near singular: [[1, 10], [0, 1]] has sigma_min
  // (sqrt(104) - 10) / 2 = 0.0990195...
  Mat<2> shear = Mat<2>::identity();
  shear(0, 1) = 10.0;
  EXPECT_NEAR(smallest_singular_value(shear), (std::sqrt(104.0) - 10.0) / 2.0, 1e-12);
}

// singular_value_at_least(M, s) is smallest_singular_value(M) >= s: checked on random matrices
// of known singular values against thresholds on either side of sigma_min (1e-6 away: far
// beyond both routes' round-off, 1e-8 at worst above), on the shear, and on a rank-one matrix.
template <int D>
void expect_at_least_agrees(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 2.0), angle(-3.2, 3.2);
  for (int trial = 0; trial < 1000; ++trial) {
    Mat<D> S;
    double least = 1e300;
    for (int k = 0; k < D; ++k) {
      S(k, k) = u(rng);
      least = std::min(least, S(k, k));
    }
    Mat<D> M;
    if constexpr (D == 2)
      M = rotation2(angle(rng)) * S * transpose(rotation2(angle(rng)));
    else
      M = rotation3(rng) * S * transpose(rotation3(rng));
    for (double s : {0.05, 0.3, 1.0, least - 1e-6, least + 1e-6}) {
      if (s <= 0.0) continue;
      EXPECT_EQ(singular_value_at_least(M, s), least >= s) << trial << " s = " << s;
    }
  }
}

TEST(SingularValue, AtLeastAgreesWithTheSmallest2D) {
  expect_at_least_agrees<2>(3);
  Mat<2> shear = Mat<2>::identity();
  shear(0, 1) = 10.0;  // sigma_min 0.0990195...
  EXPECT_TRUE(singular_value_at_least(shear, 0.0990));
  EXPECT_FALSE(singular_value_at_least(shear, 0.0991));
  EXPECT_FALSE(singular_value_at_least(outer(Vec<2>{{1.0, 2.0}}, Vec<2>{{-0.5, 3.0}}), 0.05));
  // The identity scaled: both singular values s, on the threshold's either side.
  EXPECT_TRUE(singular_value_at_least(Mat<2>::identity() * 0.5, 0.4999));
  EXPECT_FALSE(singular_value_at_least(Mat<2>::identity() * 0.5, 0.5001));
}

TEST(SingularValue, AtLeastAgreesWithTheSmallest3D) {
  expect_at_least_agrees<3>(4);
}

}  // namespace
}  // namespace flume
