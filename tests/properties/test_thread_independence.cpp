// Same input, different thread counts: bit-identical results (gather-style loops, serial
// reductions for sums, exact min reductions for the time step).
#include <gtest/gtest.h>
#include <omp.h>

#include "flume/case/build_simulation.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

ParticleSet<2> run_with_threads(const std::string& preset, int threads) {
  omp_set_num_threads(threads);
  const auto spec = test::spec_from(test::dam_break_toml(preset, 20, 0.03));
  auto sim = build_simulation<2>(spec);
  sim.set_particles_per_thread(0);  // every thread asked, on this small case too
  while (sim.time() < spec.end_time)
    sim.step(spec.end_time - sim.time());
  return sim.particles();
}

class ThreadIndependence : public ::testing::TestWithParam<std::string> {};

TEST_P(ThreadIndependence, OneTwoAndThreeThreadsGiveIdenticalParticles) {
  const int saved = omp_get_max_threads();
  const auto one = run_with_threads(GetParam(), 1);
  const auto two = run_with_threads(GetParam(), 2);
  const auto three = run_with_threads(GetParam(), 3);
  omp_set_num_threads(saved);
  ASSERT_EQ(one.n_real, two.n_real);
  for (const auto* other : {&two, &three}) {
    // Exact equality, not a tolerance: the claim is bit-identical output.
    EXPECT_TRUE(one.id == other->id);
    EXPECT_TRUE(one.x == other->x);
    EXPECT_TRUE(one.v == other->v);
    EXPECT_TRUE(one.v_half == other->v_half);
    EXPECT_TRUE(one.rho == other->rho);
    EXPECT_TRUE(one.p == other->p);
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, ThreadIndependence,
                         ::testing::Values("standard", "continuity", "csph"));

}  // namespace
}  // namespace flume
