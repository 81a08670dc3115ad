// The depth of water from the particles' masses (probes/water_depth.hpp) and the wave probes
// built on it (probes/wave_probes.hpp): exact for a lattice layer, the crest of a smooth wave
// to the B-spline's smoothing error, mirror and periodic ends, the crest unwrapped in a
// periodic tank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "flume/probes/wave_probes.hpp"
#include "flume/theory/solitary_wave.hpp"

namespace flume {
namespace {

// A lattice layer of `rows` rows at spacing dx over [0, length], masses rho0 dx^2.
ParticleSet<2> layer(double length, int rows, double dx, double rho0, double shift = 0.0) {
  ParticleSet<2> ps;
  const auto cols = static_cast<int>(std::lround(length / dx));
  std::int64_t id = 0;
  for (int c = 0; c < cols; ++c)
    for (int r = 0; r < rows; ++r) {
      double x = (c + 0.5) * dx + shift;
      if (x > length) x -= length;  // a periodic layer shifted along
      ps.add_real(id++, Vec<2>{x, (r + 0.5) * dx}, Vec<2>{}, rho0 * dx * dx, rho0, 1.2 * dx);
    }
  return ps;
}

// One particle per column at x_c carrying the mass of a column of depth eta(x_c): the depth
// profile of a smooth surface eta.
template <class F>
ParticleSet<2> columns(double length, double dx, double rho0, F eta) {
  ParticleSet<2> ps;
  const auto cols = static_cast<int>(std::lround(length / dx));
  for (int c = 0; c < cols; ++c) {
    const double x = (c + 0.5) * dx;
    ps.add_real(c, Vec<2>{x, 0.5 * eta(x)}, Vec<2>{}, rho0 * dx * eta(x), rho0, 1.2 * dx);
  }
  return ps;
}

TEST(DepthProfile, ALatticeLayerReadsItsDepthEverywhereBetweenWalls) {
  // The B-spline's shifts sum to one and the walls fold its share back: every sample reads
  // rows x dx to round-off, the samples next to the walls too (mutation: no fold at a wall
  // reads 5/6 of the depth in the first sample).
  const double dx = 0.01, rho0 = 1000.0;
  const auto ps = layer(1.0, 15, dx, rho0);
  const auto d = depth_profile(ps, nullptr, 0.0, 1.0, rho0, dx, false);
  ASSERT_EQ(d.eta.size(), 100u);
  for (double e : d.eta)
    EXPECT_NEAR(e, 0.15, 1e-13);
}

TEST(DepthProfile, AParticleNearAWallReadsAsItselfAndItsMirrorImage) {
  // A wall's ghost water is the mirror image of the water near it: a particle 0.1 dx from the
  // lower wall and one 0.3 dx from the upper wall of [0, 1] read, sample by sample, as the
  // B-spline of each plus that of its image (at -0.1 dx and 1 + 0.3 dx), computed here
  // directly. (A fold that put the image's share anywhere else, e.g. all into the first
  // sample, keeps the mass but moves it: caught here, not by a centred lattice.)
  const double dx = 0.01, rho0 = 1000.0, m = 0.05;
  ParticleSet<2> ps;
  const double a = 0.1 * dx, b = 1.0 - 0.3 * dx;
  ps.add_real(0, Vec<2>{a, 0.0}, Vec<2>{}, m, rho0, 1.2 * dx);
  ps.add_real(1, Vec<2>{b, 0.0}, Vec<2>{}, m, rho0, 1.2 * dx);
  const auto d = depth_profile(ps, nullptr, 0.0, 1.0, rho0, dx, false);
  const double unit = m / (rho0 * dx);
  for (std::size_t c = 0; c < d.eta.size(); ++c) {
    const double xc = d.centre(c);
    const double expected =
        unit * (cubic_bspline((xc - a) / dx) + cubic_bspline((xc + a) / dx) +
                cubic_bspline((xc - b) / dx) + cubic_bspline((xc - (2.0 - b)) / dx));
    EXPECT_NEAR(d.eta[c], expected, 1e-12) << c;
  }
}

TEST(DepthProfile, ALatticeLayerShiftedAcrossThePeriodicEndReadsItsDepth) {
  // A periodic tank wraps the share beyond one end into the other: a layer shifted by two
  // thirds of a spacing, its last column wrapped to the start, still reads its depth everywhere.
  const double dx = 0.01, rho0 = 1000.0;
  const auto ps = layer(1.0, 15, dx, rho0, 2.0 * dx / 3.0);
  const auto d = depth_profile(ps, nullptr, 0.0, 1.0, rho0, dx, true);
  for (double e : d.eta)
    EXPECT_NEAR(e, 0.15, 1e-13);
  // Between walls the same layer misreads at the ends (the wrapped column stands at the
  // wrong wall), which is why a periodic tank must say so.
  const auto walled = depth_profile(ps, nullptr, 0.0, 1.0, rho0, dx, false);
  double worst = 0.0;
  for (double e : walled.eta)
    worst = std::max(worst, std::abs(e - 0.15));
  EXPECT_GT(worst, 1e-3);
}

TEST(DepthProfile, TheCrestOfASolitaryWaveWithinTheSmoothingError) {
  // KdV's wave W (6.15) with A = 0.03 m on H = 0.15 m (lambda = 0.39 m) at x0 = 3.2037 m,
  // sampled every dx = 0.01 m. The B-spline smooths with variance dx^2 / 3, so the crest reads
  // low by about A (dx / lambda)^2 / 3 = 2e-5 m; the parabola through the top three samples
  // finds x0 to a small fraction of dx. Bounds: 1e-4 m on both (mutation: the parabola's
  // offset with the wrong sign puts x off by up to a spacing).
  const double dx = 0.01, rho0 = 1000.0, H = 0.15, A = 0.03, x0 = 3.2037;
  const auto ps = columns(8.0, dx, rho0, [&](double x) { return H + kdv_elevation(A, H, x - x0); });
  const auto d = depth_profile(ps, nullptr, 0.0, 8.0, rho0, dx, false);
  const Crest c = highest_crest(d);
  EXPECT_NEAR(c.x, x0, 1e-4);
  EXPECT_NEAR(c.height, H + A, 1e-4);
  EXPECT_LT(c.height, H + A);  // smoothing lowers a crest
  // A gauge reads the elevation at its place (linear between samples: 1e-4 m on a curve of
  // second derivative 2 A / lambda^2 = 0.4 /m at the crest, dx^2 / 8 of it is 5e-6 m).
  WaveProbe probe(H, {x0 + 0.2, 1.0});
  const auto r = probe(d);
  EXPECT_NEAR(r.gauges[0], kdv_elevation(A, H, 0.2), 1e-4);
  EXPECT_NEAR(r.gauges[1], kdv_elevation(A, H, 1.0 - x0), 1e-4);
  EXPECT_NEAR(r.crest_amplitude, A, 1e-4);
}

TEST(WaveProbe, TheCrestIsUnwrappedInAPeriodicTank) {
  // A crest going round a periodic tank of length 4 m: read at 3.8 m, then (having crossed the
  // end) at 0.1 m and 0.4 m, it is tracked at 3.8, 4.1, 4.4 m: the speed is the slope of
  // crest_x. Without the unwrapping it would jump back by the tank's length.
  const double dx = 0.01, rho0 = 1000.0, H = 0.15, A = 0.03, L = 4.0;
  WaveProbe probe(H, {});
  for (const double at : {3.8, 4.1, 4.4}) {
    const double x0 = std::fmod(at, L);
    const auto ps = columns(L, dx, rho0, [&](double x) {
      // the periodic image nearest x
      const double s = x - x0 - L * std::round((x - x0) / L);
      return H + kdv_elevation(A, H, s);
    });
    const auto d = depth_profile(ps, nullptr, 0.0, L, rho0, dx, true);
    EXPECT_NEAR(probe(d).crest_x, at, 1e-4) << at;
  }
  // The tracker's memory survives a checkpoint.
  WaveProbe resumed(H, {});
  resumed.restore(probe.state());
  ASSERT_EQ(probe.state().size(), 1u);
  EXPECT_EQ(resumed.state(), probe.state());
}

TEST(WaveProbe, TwoWavesAreTrackedAsTheHighestAndTheHighestOtherCrest) {
  // Two KdV waves, A = 0.04 m at x = 2.3 m and A = 0.02 m at x = 5.6 m, in a periodic tank of
  // 8 m: crest 1 is the large one, crest 2 (at least 1 m from it) the small one, each to the
  // smoothing error of the single-wave test. Then the small one goes round the end (x = 7.9 m,
  // then 0.4 m): it is tracked at 7.9 and 8.4 m. With the separation as large as the tank's
  // half there is no second crest (NaN).
  const double dx = 0.01, rho0 = 1000.0, H = 0.15, L = 8.0;
  const auto two = [&](double x1, double x2) {
    return columns(L, dx, rho0, [&](double x) {
      const auto near = [&](double x0) { return x - x0 - L * std::round((x - x0) / L); };
      return H + kdv_elevation(0.04, H, near(x1)) + kdv_elevation(0.02, H, near(x2));
    });
  };
  WaveProbe probe(H, {}, 1.0);
  for (const auto& [x2, expected] : {std::pair{5.6, 5.6}, {7.9, 7.9}, {0.4, 8.4}}) {
    const auto d = depth_profile(two(2.3, x2), nullptr, 0.0, L, rho0, dx, true);
    const auto r = probe(d);
    EXPECT_NEAR(r.crest_x, 2.3, 1e-3);
    EXPECT_NEAR(r.crest_amplitude, 0.04, 2e-4);
    EXPECT_NEAR(r.crest2_x, expected, 1e-3) << x2;
    // the large wave's tail under the small one (sech^2 of 3.3 m / 0.34 m: 1e-8 m) is nothing
    EXPECT_NEAR(r.crest2_amplitude, 0.02, 2e-4) << x2;
  }
  EXPECT_EQ(probe.state().size(), 2u);
  // Only a local maximum is a crest: 0.25 m from the large crest its flank stands at
  // 0.04 sech^2(0.25 / 0.335) = 0.024 m, higher than the small wave, yet the second crest is
  // the small wave.
  WaveProbe close(H, {}, 0.25);
  EXPECT_NEAR(close(depth_profile(two(2.3, 5.6), nullptr, 0.0, L, rho0, dx, true)).crest2_x, 5.6,
              1e-3);
  WaveProbe far(H, {}, 4.01);
  EXPECT_TRUE(
      std::isnan(far(depth_profile(two(2.3, 5.6), nullptr, 0.0, L, rho0, dx, true)).crest2_x));
}

TEST(WaterDepth, OverABeachTheSurfacesElevationAndDryIsZero) {
  // A 1:2 beach from its toe (0.5, 0) to (1, 0.25) under a 1 m tank sampled every 0.01 m: the
  // bed's height at each column's centre x is (x - 0.5) / 2 beyond the toe, 0 before it.
  const double dx = 0.01, rho0 = 1000.0;
  const auto bed = bed_heights({{0.5, 0.0, 1.0, 0.25}}, 0.0, 1.0, dx, 0.0);
  ASSERT_EQ(bed.size(), 100u);
  EXPECT_EQ(bed[10], 0.0);
  EXPECT_NEAR(bed[70], (0.705 - 0.5) / 2.0, 1e-12);
  // A layer 15 rows deep over the flat part only (x < 0.5): its depth where the bed is flat,
  // and over the beach the elevation where at least half a spacing of water stands, 0 where dry.
  auto ps = layer(0.5, 15, dx, rho0);
  const auto d = depth_profile(ps, nullptr, 0.0, 1.0, rho0, dx, false, &bed);
  EXPECT_NEAR(d.eta[20], 0.15, 1e-12);
  EXPECT_EQ(d.eta[60], 0.0);  // dry beach
  // The first beach column (centre 0.505 m) still holds the B-spline's tail of the layer.
  const auto bare = depth_profile(ps, nullptr, 0.0, 1.0, rho0, dx, false);
  EXPECT_NEAR(d.eta[50], bare.eta[50] + bed[50], 1e-15);
  EXPECT_GE(bare.eta[50], 0.5 * dx);
}

TEST(StillWater, BedPressureLevelAndDensityOfAHydrostaticLayer) {
  // A lattice layer of 15 rows whose pressure is hydrostatic, p = rho0 g (H - y), reads the
  // bed pressure rho0 g H exactly, the level H exactly (n rows have mean height n dx / 2) and
  // the largest density deviation it was given.
  const double dx = 0.01, rho0 = 1000.0, g = 9.81, H = 0.15;
  auto ps = layer(1.0, 15, dx, rho0);
  for (std::size_t i = 0; i < ps.n_real; ++i)
    ps.p[i] = rho0 * g * (H - ps.x[i][1]);
  ps.rho[7] = 1003.0;
  const auto r = read_still_water(ps, 0.1, 0.9, 0.0, rho0, g, dx);  // the middle 80 %
  EXPECT_NEAR(r.bed_pressure, rho0 * g * H, 1e-9);
  EXPECT_NEAR(r.water_level, H, 1e-14);
  EXPECT_NEAR(r.density_deviation, 0.003, 1e-15);
}

}  // namespace
}  // namespace flume
