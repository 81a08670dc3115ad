// The threads a step runs on (sim/thread_team.hpp): at most one per particles_per_thread real
// particles, at least one, never more than asked; OpenMP's count put back after the step.
//
// Tolerance: none; thread counts are integers.
#include <gtest/gtest.h>
#include <omp.h>

#include "flume/case/build_simulation.hpp"
#include "flume/sim/thread_team.hpp"
#include "support/small_cases.hpp"

namespace flume {
namespace {

TEST(TeamSize, OneThreadPerThousandParticlesAtMostAndAtLeastOne) {
  EXPECT_EQ(team_size(430, 2, 1000), 1);
  EXPECT_EQ(team_size(1999, 2, 1000), 1);
  EXPECT_EQ(team_size(2000, 2, 1000), 2);
  EXPECT_EQ(team_size(2999, 4, 1000), 2);
  EXPECT_EQ(team_size(100000, 2, 1000), 2);
  EXPECT_EQ(team_size(0, 2, 1000), 1);
  EXPECT_EQ(team_size(100000, 1, 1000), 1);
  // 0 particles per thread: every thread asked, at any size.
  EXPECT_EQ(team_size(10, 3, 0), 3);
}

TEST(ThreadTeam, ParallelRegionsInItsScopeRunOnItsCountAndTheCountComesBack) {
  const ThreadTeam outer(3);  // and the test's starting count back at the end
  {
    const ThreadTeam team(1);
    int started = 0;
#pragma omp parallel
    {
#pragma omp single
      started = omp_get_num_threads();
    }
    EXPECT_EQ(started, 1);
  }
  EXPECT_EQ(omp_get_max_threads(), 3);
}

TEST(ThreadTeam, ASmallSimulationStepsOnOneThreadUnlessToldOtherwise) {
  const ThreadTeam outer(2);
  // 20 x 20 = 400 particles: one thread at the default 1,000 particles a thread.
  const auto spec = test::spec_from(test::dam_break_toml("standard", 20, 0.01));
  auto sim = build_simulation<2>(spec);
  ASSERT_LT(sim.particles().n_real, kParticlesPerThread);
  EXPECT_EQ(sim.step_threads(), 1);
  sim.step(1.0);
  EXPECT_EQ(sim.last_step_threads(), 1);
  EXPECT_EQ(omp_get_max_threads(), 2);
  sim.set_particles_per_thread(0);
  EXPECT_EQ(sim.step_threads(), 2);
  sim.step(1.0);
  EXPECT_EQ(sim.last_step_threads(), 2);
  sim.set_particles_per_thread(100);  // 400 particles: up to 4 threads, 2 asked
  EXPECT_EQ(sim.step_threads(), 2);
}

}  // namespace
}  // namespace flume
