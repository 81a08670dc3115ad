// Unit tests of the probe-versus-reference comparison (src/flume/validation/curve_compare.*):
// linear interpolation, and compare_curve's scaling, windowing and relative errors; the mean and
// the least-squares slope over a window (compare_over_window).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "flume/validation/curve_compare.hpp"

namespace flume {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

TEST(CurveCompare, InterpolateIsExactAtTheNodes) {
  const std::vector<double> xs{0.0, 0.3, 0.7, 1.6, 2.0};
  const std::vector<double> ys{1.0, -2.0, 5.5, 0.25, 3.0};
  for (std::size_t k = 0; k < xs.size(); ++k)
    // At a node the weight is 0 (or the node is an end point): the value is returned unchanged.
    EXPECT_EQ(interpolate(xs, ys, xs[k]), ys[k]) << "node " << k;
}

TEST(CurveCompare, InterpolateIsExactForLinearData) {
  // y = 3 x - 2 on an uneven grid: linear interpolation reproduces it up to round-off (a
  // weight, a difference and a multiply-add: a few ulp of |y| <= ~10).
  const std::vector<double> xs{-1.0, -0.2, 0.05, 0.9, 1.0, 2.5, 4.0};
  std::vector<double> ys;
  for (double x : xs)
    ys.push_back(3.0 * x - 2.0);
  for (double x = -1.0; x <= 4.0; x += 0.0625) {
    EXPECT_NEAR(interpolate(xs, ys, x), 3.0 * x - 2.0, 16.0 * kEps * 10.0) << "x " << x;
  }
  // Dyadic nodes and query points: exact.
  const std::vector<double> dx{0.0, 0.5, 1.0, 2.0};
  const std::vector<double> dy{1.0, 2.0, 3.0, 5.0};  // y = 2 x + 1
  EXPECT_EQ(interpolate(dx, dy, 0.25), 1.5);
  EXPECT_EQ(interpolate(dx, dy, 1.75), 4.5);
}

TEST(CurveCompare, InterpolateIsPiecewiseLinear) {
  const std::vector<double> xs{0.0, 1.0, 3.0};
  const std::vector<double> ys{0.0, 2.0, 1.0};
  EXPECT_EQ(interpolate(xs, ys, 0.5), 1.0);   // dyadic: exact
  EXPECT_EQ(interpolate(xs, ys, 2.0), 1.5);   // halfway on the second segment: exact
  EXPECT_EQ(interpolate(xs, ys, 2.5), 1.25);  // exact
}

TEST(CurveCompare, InterpolateThrowsOutsideTheSeries) {
  const std::vector<double> xs{0.0, 1.0, 2.0};
  const std::vector<double> ys{0.0, 1.0, 4.0};
  EXPECT_THROW(interpolate(xs, ys, -1e-12), std::out_of_range);
  EXPECT_THROW(interpolate(xs, ys, 2.0 + 1e-12), std::out_of_range);
  EXPECT_THROW(interpolate({}, {}, 0.0), std::out_of_range);
  EXPECT_EQ(interpolate({1.0}, {7.0}, 1.0), 7.0);  // a single point is its own window
}

// Regression: a NaN abscissa is not "within [xs.front(), xs.back()]": interpolate() throws, and
// compare_curve skips such a reference point instead of comparing it with the last value.
TEST(CurveCompare, InterpolateThrowsOnNaN) {
  const std::vector<double> xs{0.0, 1.0, 2.0};
  const std::vector<double> ys{0.0, 1.0, 4.0};
  EXPECT_THROW(interpolate(xs, ys, std::numeric_limits<double>::quiet_NaN()), std::out_of_range);
}

TEST(CurveCompare, ScalesTimeAndValueSkipsOutsideAndComputesRelativeErrors) {
  // Probe: t = 0, 0.5, 1.0, 1.5 s, y = 0.2, 0.4, 0.8, 1.0 m. With time_scale 0.5 s and
  // value_scale 0.4 m the simulated curve is T = 0, 1, 2, 3 and Y = 0.5, 1.0, 2.0, 2.5.
  const std::vector<double> t{0.0, 0.5, 1.0, 1.5};
  const std::vector<double> y{0.2, 0.4, 0.8, 1.0};
  // Reference points: T = -0.5 (before the window, skipped), 0.5, 2.0, 2.5, 3.0 (the end, kept),
  // 3.5 (after, skipped).
  const std::vector<double> rx{-0.5, 0.5, 2.0, 2.5, 3.0, 3.5};
  const std::vector<double> ry{9.0, 0.8, 2.0, 2.0, 2.0, 9.0};
  const auto pts = compare_curve(t, y, rx, ry, 0.5, 0.4);
  ASSERT_EQ(pts.size(), 4u);
  // By hand: Y(0.5) = 0.75, |0.75 - 0.8| / 0.8 = 0.0625; Y(2) = 2, error 0; Y(2.5) = 2.25,
  // error 0.125; Y(3) = 2.5, error 0.25.
  const std::vector<double> want_x{0.5, 2.0, 2.5, 3.0};
  const std::vector<double> want_ref{0.8, 2.0, 2.0, 2.0};
  const std::vector<double> want_val{0.75, 2.0, 2.25, 2.5};
  const std::vector<double> want_err{0.0625, 0.0, 0.125, 0.25};
  for (std::size_t k = 0; k < pts.size(); ++k) {
    EXPECT_EQ(pts[k].x, want_x[k]) << k;  // copied from the reference
    EXPECT_EQ(pts[k].reference, want_ref[k]) << k;
    // y / value_scale rounds (0.2 / 0.4 etc. are not dyadic), then one interpolation: a few ulp.
    EXPECT_NEAR(pts[k].value, want_val[k], 8.0 * kEps * want_val[k]) << k;
    // |value - reference| / |reference| with value a few ulp off: error off by a few ulp of
    // value / reference <= ~1.3.
    EXPECT_NEAR(pts[k].error, want_err[k], 16.0 * kEps) << k;
  }
}

TEST(CurveCompare, ErrorIsRelativeToTheReferenceMagnitude) {
  // Negative reference values: the error uses |reference|.
  const std::vector<double> t{0.0, 2.0};
  const std::vector<double> y{-2.0, -2.0};
  const auto pts = compare_curve(t, y, {1.0}, {-4.0}, 1.0, 1.0);
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_EQ(pts[0].value, -2.0);  // dyadic: exact
  EXPECT_EQ(pts[0].error, 0.5);   // |-2 - -4| / 4, exact
}

TEST(CurveCompare, EmptyProbeOrReferenceGivesNoPoints) {
  EXPECT_TRUE(compare_curve({}, {}, {0.0, 1.0}, {1.0, 1.0}, 1.0, 1.0).empty());
  EXPECT_TRUE(compare_curve({0.0, 1.0}, {1.0, 1.0}, {}, {}, 1.0, 1.0).empty());
  // A reference entirely after the simulated window.
  EXPECT_TRUE(compare_curve({0.0, 1.0}, {1.0, 1.0}, {2.0, 3.0}, {1.0, 1.0}, 1.0, 1.0).empty());
}

// A probe x(t) = 0.1 + 0.9 t + 0.01 sin(50 t) against a reference front v t with v = 0.85 over
// t in [0.48, 0.6]: the slope compared is the probe's least-squares slope at the reference's
// points, computed here independently with the closed form; the mean likewise.
TEST(CurveCompare, WindowStatisticsAreTheMeanAndTheLeastSquaresSlope) {
  std::vector<double> t, y, rx, ry;
  for (int k = 0; k <= 600; ++k) {
    t.push_back(0.001 * k);
    y.push_back(0.1 + 0.9 * t.back() + 0.01 * std::sin(50.0 * t.back()));
  }
  for (int k = 0; k <= 20; ++k) {
    rx.push_back(0.03 * k);
    ry.push_back(0.85 * rx.back());
  }
  // The reference points in [0.48, 0.6]: 0.48, 0.51, ..., 0.6 (5 points).
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t k = 0; k < rx.size(); ++k) {
    if (rx[k] < 0.48 || rx[k] > 0.6) continue;
    const double v = interpolate(t, y, rx[k]);
    sx += rx[k];
    sy += v;
    sxx += rx[k] * rx[k];
    sxy += rx[k] * v;
    ++n;
  }
  ASSERT_EQ(n, 5);
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const auto s =
      compare_over_window(t, y, rx, ry, 1.0, 1.0, false, CurveStatistic::slope, 0.48, 0.6);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_NEAR(s[0].value, slope, 1e-12);  // two formulas of the same sums: round-off
  EXPECT_NEAR(s[0].reference, 0.85, 1e-12);
  EXPECT_NEAR(s[0].error, std::abs(slope - 0.85) / 0.85, 1e-12);
  EXPECT_NEAR(s[0].x, 0.6, 1e-15);
  const auto m =
      compare_over_window(t, y, rx, ry, 1.0, 1.0, false, CurveStatistic::mean, 0.48, 0.6);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_NEAR(m[0].value, sy / n, 1e-12);
  EXPECT_NEAR(m[0].reference, 0.85 * 0.54, 1e-12);
  // Pointwise over the window: just the five points.
  EXPECT_EQ(compare_over_window(t, y, rx, ry, 1.0, 1.0, false, CurveStatistic::pointwise, 0.48, 0.6)
                .size(),
            5u);
}

TEST(CurveCompare, AWindowTheRunDidNotCoverIsNotSummarised) {
  const std::vector<double> t{0.0, 0.5}, y{0.0, 0.5};
  const std::vector<double> rx{0.4, 0.5, 0.6}, ry{0.4, 0.5, 0.6};
  EXPECT_TRUE(
      compare_over_window(t, y, rx, ry, 1.0, 1.0, false, CurveStatistic::slope, 0.4, 0.6).empty());
  EXPECT_EQ(
      compare_over_window(t, y, rx, ry, 1.0, 1.0, false, CurveStatistic::slope, 0.4, 0.5).size(),
      1u);
}

}  // namespace
}  // namespace flume
