// The crest's centre (probes/water_depth.hpp crest_centre, the wave probe's crest_centre_x): the
// centroid of the upper half of the crest, a position that does not hop where the top is flat.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flume/probes/wave_probes.hpp"
#include "flume/theory/solitary_wave.hpp"

namespace flume {
namespace {

constexpr double kH = 0.15, kA = 0.03, kDx = 0.01;

// The depth profile eta(x) sampled every kDx over [0, length].
template <class F>
DepthProfile profile(double length, bool periodic, F eta) {
  DepthProfile d;
  d.dx = kDx;
  d.periodic = periodic;
  const auto n = static_cast<std::size_t>(std::lround(length / kDx));
  for (std::size_t c = 0; c < n; ++c)
    d.eta.push_back(eta(d.centre(c)));
  return d;
}

TEST(CrestCentre, OfASymmetricHumpIsItsCrest) {
  // A KdV wave (lambda = 0.335 m) off the samples' grid: the centroid of the samples above half
  // its height is the crest to the sampling's error. That error comes from the run's two ends,
  // where the excess enters linearly between samples: each end is off by at most its slope
  // times dx^2 / 8 against a total weight of ~0.5 A lambda, i.e. ~1e-5 m here; 1e-4 m leaves
  // room and is still 1 % of a spacing.
  const double x0 = 3.2037;
  const auto d = profile(8.0, false, [&](double x) { return kH + kdv_elevation(kA, kH, x - x0); });
  const Crest c = highest_crest(d);
  EXPECT_NEAR(crest_centre(d, c, kH), x0, 1e-4);
}

TEST(CrestCentre, AFlatTopWithABumpDoesNotHop) {
  // A wave whose top is flat over 0.4 m (a crest a few particles wide, noisy): a 0.1 mm bump at
  // 0.15 m from the middle takes the highest sample there, the centre stays in the middle. The
  // bump's own weight, 1e-4 m x dx at 0.15 m against the upper half's ~A x 0.6 m, moves it by
  // ~1e-5 m: bound 1e-4 m. (The highest sample is 0.15 m off: what crest_x reads.)
  const double x0 = 4.0;
  const auto d = profile(8.0, false, [&](double x) {
    const double s = std::abs(x - x0);
    const double top = s < 0.2 ? kH + kA : kH + kdv_elevation(kA, kH, s - 0.2);
    return top + (std::abs(x - x0 - 0.15) < 0.5 * kDx ? 1e-4 : 0.0);
  });
  const Crest c = highest_crest(d);
  EXPECT_NEAR(c.x, x0 + 0.15, kDx);
  EXPECT_NEAR(crest_centre(d, c, kH), x0, 1e-4);
  // and the probe reports it beside the crest
  WaveProbe probe(kH, {});
  const auto r = probe(d);
  EXPECT_NEAR(r.crest_x, x0 + 0.15, kDx);
  EXPECT_NEAR(r.crest_centre_x, x0, 1e-4);
}

TEST(CrestCentre, AShelfBelowHalfTheHeightDoesNotPullIt) {
  // A shelf 0.3 A high over the 2 m behind the wave (the water a damped wave leaves behind)
  // lies below the half-height level, so the centre stays at the crest (1e-3 m: the shelf
  // raises the flank behind by 0.3 A, which moves the run's rear end by a sample or so). The
  // centroid of all the excess over the still depth would sit ~0.5 m behind.
  const double x0 = 5.0;
  const auto d = profile(8.0, false, [&](double x) {
    const double shelf = (x < x0 && x > x0 - 2.0) ? 0.3 * kA : 0.0;
    return kH + std::max(kdv_elevation(kA, kH, x - x0), shelf);
  });
  EXPECT_NEAR(crest_centre(d, highest_crest(d), kH), x0, 1e-3);
}

TEST(CrestCentre, IsUnwrappedWithTheCrestInAPeriodicTank) {
  // A crest read at 3.8 m, then at 0.03 m of a 4 m periodic tank (its upper half straddling
  // the end): the probe reads the centre at 4.03 m, like the crest.
  const double L = 4.0;
  WaveProbe probe(kH, {});
  for (const double at : {3.8, 4.03}) {
    const double x0 = std::fmod(at, L);
    const auto d = profile(L, true, [&](double x) {
      return kH + kdv_elevation(kA, kH, x - x0 - L * std::round((x - x0) / L));
    });
    const auto r = probe(d);
    EXPECT_NEAR(r.crest_x, at, 1e-3) << at;
    EXPECT_NEAR(r.crest_centre_x, at, 1e-4) << at;
  }
}

TEST(CrestCentre, AWallEndsTheCrest) {
  // A wave reflecting at the wall x = 0, its crest at the wall: the centre is the centroid of
  // the half inside the tank, computed here directly from the samples, not a point beyond the
  // wall (the mirror half). No crest above the still depth: the crest's own position.
  const auto d = profile(4.0, false, [&](double x) { return kH + kdv_elevation(kA, kH, x); });
  const Crest c = highest_crest(d);
  double sw = 0.0, swx = 0.0;
  for (std::size_t k = 0; k < d.eta.size(); ++k) {
    const double w = d.eta[k] - (kH + 0.5 * (c.height - kH));
    if (w <= 0.0) break;
    sw += w;
    swx += w * d.centre(k);
  }
  EXPECT_NEAR(crest_centre(d, c, kH), swx / sw, 1e-12);
  EXPECT_GT(swx / sw, 0.05);
  const auto flat = profile(4.0, false, [](double) { return kH; });
  const Crest none = highest_crest(flat);
  EXPECT_EQ(crest_centre(flat, none, kH), none.x);
}

}  // namespace
}  // namespace flume
