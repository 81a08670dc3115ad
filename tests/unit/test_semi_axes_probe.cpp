// The semi-axes probe (src/flume/probes/semi_axes.hpp): relative to its first call, it follows
// a cloud moved by a linear map exactly, whatever the cloud's sampling.
#include <gtest/gtest.h>

#include <random>

#include "flume/probes/semi_axes.hpp"

namespace flume {
namespace {

TEST(SemiAxesProbe, FollowsALinearStretchOfAnyCloud) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ParticleSet<2> ps;
  while (ps.n_real < 300) {
    const Vec<2> x{{u(rng), u(rng)}};
    if (norm(x) <= 1.0)
      ps.add_real(static_cast<std::int64_t>(ps.n_real), x, Vec<2>{}, 1.0 + 0.1 * u(rng), 1000.0,
                  0.1);
  }
  SemiAxesProbe probe({1.0, 1.0});
  const auto start = probe(ps);
  // The nominal semi-axes at the start, exactly (the reference is the first call).
  EXPECT_EQ(start[0], 1.0);
  EXPECT_EQ(start[1], 1.0);
  // Stretched by diag(0.5, 2) and shifted: semi-axes 0.5 and 2 to round-off (sums of 300
  // terms: 1e-13 relative is ample; a missing square root or factor 2 gives O(1)).
  for (std::size_t i = 0; i < ps.n_real; ++i)
    ps.x[i] = Vec<2>{{0.5 * ps.x[i][0] + 3.0, 2.0 * ps.x[i][1] - 1.0}};
  const auto now = probe(ps);
  EXPECT_NEAR(now[0], 0.5, 1e-13);
  EXPECT_NEAR(now[1], 2.0, 1e-13);
}

}  // namespace
}  // namespace flume
