// The breaking detector (probes/breaking.hpp) and the shoaling probe's Grilli prediction
// (probes/wave_probes.hpp) on hand-made particle sets and crest readings.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flume/probes/breaking.hpp"
#include "flume/probes/wave_probes.hpp"

namespace flume {
namespace {

// A layer of `rows` rows and `cols` columns at spacing dx from the origin, and, when gap > 0,
// a jet of 3 rows over the columns from x_jet, standing gap above the layer's top row.
ParticleSet<2> layer_with_jet(int rows, int cols, double dx, double gap, double x_jet) {
  ParticleSet<2> ps;
  std::int64_t id = 0;
  const auto add = [&](double x, double y) {
    Vec<2> p;
    p[0] = x;
    p[1] = y;
    ps.add_real(id++, p, Vec<2>{}, 1.0, 1000.0, 1.3 * dx);
  };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      add((c + 0.5) * dx, (r + 0.5) * dx);
  if (gap > 0.0)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c)
        add(x_jet + (c + 0.5) * dx, (rows - 0.5) * dx + gap + r * dx);
  return ps;
}

TEST(BreakingProbe, AJetOverATubeOfAirIsBreakingWhereItStands) {
  const double dx = 0.01;
  BreakingProbe probe(dx, 4.0);
  // A settled layer: every gap in a column is one spacing; not broken.
  auto flat = layer_with_jet(10, 60, dx, 0.0, 0.0);
  std::vector<char> all(flat.n_real, 1);
  auto r = probe(flat, all, 0.0, 0.5);
  EXPECT_NEAR(r[0], dx, 1e-12);
  EXPECT_EQ(r[1], 0.0);
  EXPECT_EQ(r[2], 0.0);
  // A jet 3 spacings over the layer (gap 3 dx < 4 dx): not yet.
  auto low = layer_with_jet(10, 60, dx, 3.0 * dx, 0.30);
  all.assign(low.n_real, 1);
  r = probe(low, all, 0.0, 0.6);
  EXPECT_NEAR(r[0], 3.0 * dx, 1e-12);
  EXPECT_EQ(r[1], 0.0);
  // 6 spacings of air under the jet over x = 0.30-0.34 m: broken at t = 0.7 s, in the first
  // column (2 dx wide) that holds the gap, [0.30, 0.32): centre 0.31 m.
  auto high = layer_with_jet(10, 60, dx, 6.0 * dx, 0.30);
  all.assign(high.n_real, 1);
  r = probe(high, all, 0.0, 0.7);
  EXPECT_NEAR(r[0], 6.0 * dx, 1e-12);
  EXPECT_EQ(r[1], 0.7);
  EXPECT_NEAR(r[2], 0.31, 1e-12);
  // The first breaking is kept, also through a checkpoint.
  r = probe(high, all, 0.0, 0.8);
  EXPECT_EQ(r[1], 0.7);
  BreakingProbe resumed(dx, 4.0);
  resumed.restore(probe.state());
  r = resumed(flat, std::vector<char>(flat.n_real, 1), 0.0, 0.9);
  EXPECT_EQ(r[1], 0.7);
  EXPECT_NEAR(r[2], 0.31, 1e-12);
  // A pocket at the foot of a column (a wall under it: one row, then air, then water) is not a
  // tube of air: the gap's lower side must stand two spacings above the column's lowest.
  auto pocket = layer_with_jet(1, 60, dx, 6.0 * dx, 0.30);
  BreakingProbe fresh(dx, 4.0);
  EXPECT_EQ(fresh(pocket, std::vector<char>(pocket.n_real, 1), 0.0, 0.7)[1], 0.0);
  // Particles outside the main body (spray) do not count.
  std::vector<char> body(high.n_real, 1);
  for (std::size_t i = 600; i < high.n_real; ++i)
    body[i] = 0;
  BreakingProbe other(dx, 4.0);
  EXPECT_EQ(other(high, body, 0.0, 0.7)[1], 0.0);
}

TEST(ShoalingProbe, IncidentAmplitudeAndGrilliPrediction) {
  // H = 0.15 m, a 1:15 beach from x = 3 m: 16.9 s^2 = 0.0751.
  ShoalingProbe probe(0.15, 1.0 / 15.0, 3.0);
  auto r = probe(1.0, 0.08);  // the crest offshore: its amplitude is the incident one so far
  EXPECT_EQ(r[0], 0.08);
  r = probe(2.8, 0.03);  // the last reading more than H offshore: A/H = 0.2 > 0.0751, breaks
  EXPECT_EQ(r[0], 0.03);
  EXPECT_NEAR(r[1], 1.521 / 15.0 / std::sqrt(0.2), 1e-15);  // W (6.20)
  EXPECT_EQ(r[2], 1.0);
  r = probe(2.86, 0.04);  // within H of the toe: kept
  EXPECT_EQ(r[0], 0.03);
  r = probe(3.2, 0.05);  // over the beach: kept
  EXPECT_EQ(r[0], 0.03);
  r = probe(2.95, 0.07);  // a reflected crest back offshore: still the incident wave's
  EXPECT_EQ(r[0], 0.03);
  // On 1:8 (16.9 / 64 = 0.264) the same wave does not break (W Table 6.13's "No" for A/H 0.2).
  ShoalingProbe steep(0.15, 1.0 / 8.0, 3.0);
  EXPECT_EQ(steep(2.8, 0.03)[2], 0.0);
  ShoalingProbe resumed(0.15, 1.0 / 15.0, 3.0);
  resumed.restore(probe.state());
  EXPECT_EQ(resumed(2.8, 0.09)[0], 0.03);
}

}  // namespace
}  // namespace flume
