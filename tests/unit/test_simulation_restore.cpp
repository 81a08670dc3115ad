// Simulation::restore in a simulation that has already stepped: what it knew of the particles
// before (the bounding box its last drift's pass found, which the next sort by cell would
// otherwise take) is forgotten, so the restored state steps exactly as in a fresh simulation.
//
// Tolerance: none; the same state and the same steps give the same bits.
#include <gtest/gtest.h>

#include "flume/case/build_simulation.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

TEST(SimulationRestore, ARestoredStateStepsAsInAFreshSimulation) {
  const auto spec = test::spec_from(test::dam_break_toml("standard", 8, 0.1));
  auto stepped = build_simulation<2>(spec);
  for (int s = 0; s < 5; ++s)
    stepped.step(1.0);
  // The column lifted by its height, to the tank's lid: over the stepped simulation's box the
  // grid would bin its upper part into its top layer of cells. The pairs would still all be found
  // (clamped particles share a cell, sorted by x), but in another order, so the sums would differ
  // in their last bits.
  auto moved = stepped.particles();
  const double a = 0.05715;
  for (std::size_t i = 0; i < moved.n_real; ++i)
    moved.x[i][1] += a;
  const auto state = stepped.state();
  auto fresh = build_simulation<2>(spec);
  fresh.restore(moved, state);
  stepped.restore(moved, state);
  for (int s = 0; s < 10; ++s) {
    fresh.step(1.0);
    stepped.step(1.0);
  }
  const auto& p = fresh.particles();
  const auto& q = stepped.particles();
  ASSERT_EQ(p.n_real, q.n_real);
  for (std::size_t i = 0; i < p.n_real; ++i) {
    EXPECT_EQ(p.x[i], q.x[i]) << i;
    EXPECT_EQ(p.v[i], q.v[i]) << i;
    EXPECT_EQ(p.rho[i], q.rho[i]) << i;
  }
}

}  // namespace
}  // namespace flume
