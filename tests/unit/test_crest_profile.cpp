// The crest's profile against the KdV solitary wave (probes/crest_profile.hpp): the width fitted
// to a sech^2 profile of known width, and the shape deviation from KdV's profile against an
// independent quadrature of its definition.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "flume/probes/crest_profile.hpp"

namespace flume {
namespace {

constexpr double kH = 0.15;    // still depth, m
constexpr double kA = 0.03;    // amplitude, m (lambda_KdV = 0.387 m)
constexpr double kDx = 0.005;  // sample spacing, m

double sech2(double z) {
  const double c = std::cosh(z);
  return 1.0 / (c * c);
}

// A tank [0, length] sampled every kDx with eta = H + A sech^2((x - xc) / lambda).
DepthProfile wave(double length, double xc, double lambda, bool periodic = false) {
  DepthProfile d;
  d.x_lo = 0.0;
  d.dx = kDx;
  d.periodic = periodic;
  const auto n = static_cast<std::size_t>(std::lround(length / kDx));
  for (std::size_t c = 0; c < n; ++c) {
    double s = d.centre(c) - xc;
    if (periodic) s -= length * std::round(s / length);
    d.eta.push_back(kH + kA * sech2(s / lambda));
  }
  return d;
}

TEST(CrestProfile, AKdVWaveReadsItsOwnWidthAndNoShapeDeviation) {
  // The crest between samples (xc = 2.0012 m): the profile's linear interpolation errs by
  // about A (dx / lambda)^2 / 8 ~ 6e-7 m, 2e-5 of A, so 1e-4 bounds both the width's relative
  // error and the shape deviation (golden section: 80 steps shrink the bracket to 1e-16).
  const double lk = kdv_width(kA, kH);
  const auto c = crest_profile(wave(6.0, 2.0012, lk), kH, 2.0012, kA);
  EXPECT_NEAR(c.width / lk, 1.0, 1e-4);
  EXPECT_LT(c.shape, 1e-4);
}

TEST(CrestProfile, AWiderWaveReadsItsWidthAndTheShapeOfItsDefinition) {
  // lambda = 1.3 lambda_KdV: the fit finds it (1e-4 as above); the shape is the RMS over
  // |s| <= 3 lambda_KdV of sech^2(s / lambda) - sech^2(s / lambda_KdV), computed here by
  // Simpson's rule over the continuous window (the probe sums over the offsets k dx: the two
  // agree to O(dx / window) = 1e-2 relative at most, about 1e-3 here; 5e-3 allowed).
  // (Mutations: a window of 1 lambda_KdV, or the RMS without the square root or over A^2, fail.)
  const double lk = kdv_width(kA, kH), l = 1.3 * lk;
  const auto c = crest_profile(wave(6.0, 3.0, l), kH, 3.0, kA);
  EXPECT_NEAR(c.width / l, 1.0, 1e-4);
  const int n = 20000;
  const double a = -kCrestWindow * lk, b = kCrestWindow * lk, step = (b - a) / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double s = a + k * step;
    const double e = sech2(s / l) - sech2(s / lk);
    sum += (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0)) * e * e;
  }
  const double rms = std::sqrt(sum * step / 3.0 / (b - a));
  EXPECT_NEAR(c.shape / rms, 1.0, 5e-3);
  EXPECT_GT(rms, 0.05);  // the check can see a difference: about 0.37 x 0.3 of A
}

TEST(CrestProfile, AHalfWaveAtAWallUsesTheTankSideOnly) {
  // The crest at the wall (a mound's start): the offsets beyond the wall are left out, and the
  // half inside still reads the width (a window that read the constant end value beyond the
  // wall would widen it).
  const double lk = kdv_width(kA, kH);
  const auto c = crest_profile(wave(6.0, 0.0, 0.8 * lk), kH, 0.0, kA);
  EXPECT_NEAR(c.width / (0.8 * lk), 1.0, 1e-3);
}

TEST(CrestProfile, APeriodicTankWrapsTheWindowAround) {
  // A wave across the seam of a 4 m periodic tank, its crest unwrapped two laps on (x = 3.9 +
  // 8 m): the same width and shape as the same wave in the middle of the tank.
  const double lk = kdv_width(kA, kH), l = 1.1 * lk;
  const auto seam = crest_profile(wave(4.0, 3.9, l, true), kH, 11.9, kA);
  const auto mid = crest_profile(wave(4.0, 2.0, l, true), kH, 2.0, kA);
  EXPECT_NEAR(seam.width / l, 1.0, 1e-4);
  EXPECT_NEAR(seam.shape, mid.shape, 1e-6);
}

TEST(CrestProfile, TheFittedAmplitudeIsTheProfilesOwnWhateverTheHeightGiven) {
  // A sech^2 wave of amplitude kA and width 1.2 lambda_KdV(kA), read with a wrong height (the
  // probe's one-sample height, here 8 % low) and a crest place one sample off (its parabola
  // vertex): the fit, A' and lambda' both free, finds kA. The place error e costs the fit about
  // (e / lambda)^2 = 2e-4 of A; the interpolation 2e-5 (first test): 5e-4 allowed.
  // (Mutations: A' = sum eta phi / sum phi, or the search on sum eta phi alone, fail.)
  const double lk = kdv_width(kA, kH), l = 1.2 * lk;
  const auto c = crest_profile(wave(6.0, 3.0, l), kH, 3.0 + kDx, 0.92 * kA);
  EXPECT_NEAR(c.fit_amplitude / kA, 1.0, 5e-4);
}

TEST(CrestProfile, TheFittedAmplitudeAveragesOutSampleNoise) {
  // Each sample off by +-0.1 A in a fixed pattern (a few particles' worth at the crest): the
  // highest sample then reads up to 10 % high, while the fit's error is about the noise's size
  // over the square root of the samples within a width (0.1 A / sqrt(2 lambda / dx) = 0.8 %
  // here); 2 % allowed, 5 times less than the highest sample's error.
  const double lk = kdv_width(kA, kH);
  DepthProfile d = wave(6.0, 3.0, lk);
  double highest = 0.0;
  for (std::size_t c = 0; c < d.eta.size(); ++c) {
    d.eta[c] += 0.1 * kA * std::sin(2.3 * static_cast<double>(c * c));
    highest = std::max(highest, d.eta[c] - kH);
  }
  const auto fit = crest_profile(d, kH, 3.0, highest);
  EXPECT_NEAR(fit.fit_amplitude / kA, 1.0, 0.02);
  EXPECT_GT(highest / kA - 1.0, 0.05);  // the test can see the difference
}

TEST(CrestProfile, NoCrestReadsZero) {
  const auto d = wave(6.0, 3.0, 0.3);
  const auto c = crest_profile(d, kH, 3.0, 0.0);
  EXPECT_EQ(c.width, 0.0);
  EXPECT_EQ(c.shape, 0.0);
  EXPECT_EQ(c.fit_amplitude, 0.0);
}

}  // namespace
}  // namespace flume
