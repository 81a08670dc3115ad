// The incompressible pressure of an ellipsoid in a straining flow
// (src/flume/case/affine_flow_pressure.hpp), against BL 5.2's ODE for the drop, the free-surface
// condition and the momentum balance by finite differences.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "flume/case/affine_flow_pressure.hpp"

namespace flume {
namespace {

constexpr double kRho0 = 1000.0;

FluidBlock ellipse(double a, double b, double A) {
  FluidBlock block;
  block.shape = "ellipsoid";
  block.min = {1.0 - a, -2.0 - b};  // centred at (1, -2): the centre is not the origin
  block.max = {1.0 + a, -2.0 + b};
  block.velocity = {0.0, 0.0};
  block.velocity_gradient = {-A, 0.0, 0.0, A};
  return block;
}

// dg_k/dt = P / r_k^2 - g_k^2 against BL 5.2's dA/dt = A^2 (a^2 - b^2) / (a^2 + b^2), written
// here from the case's ODE, not from the header's P (to round-off: a few operations on 1e4).
TEST(AffineFlowPressure, GivesBonetLoksDropEquation) {
  for (const auto& [a, b] :
       {std::array{1.0, 1.0}, std::array{0.8, 1.25}, std::array{0.5, 2.0}, std::array{0.6, 1.5}}) {
    const double A = 100.0;
    const double P = affine_flow_pressure_scale(ellipse(a, b, A), 2);
    const double dA_dt = A * A * (a * a - b * b) / (a * a + b * b);
    EXPECT_NEAR(P / (b * b) - A * A, dA_dt, 1e-12 * A * A) << a << " x " << b;
    EXPECT_NEAR(P / (a * a) - A * A, -dA_dt, 1e-12 * A * A) << a << " x " << b;  // tr G stays 0
  }
}

// p = 0 on the surface, rho0 P / 2 at the centre; -grad p / rho0 = (dG/dt + G^2)(x - c), taken
// by central differences (step 1e-4 m on a quadratic: exact but for round-off, 1e-6 relative).
TEST(AffineFlowPressure, FreeSurfaceAndMomentumBalance2D) {
  const double a = 0.6, b = 1.5, A = 100.0;  // a b != 1: sum r^-2 differs from sum r^2
  const FluidBlock block = ellipse(a, b, A);
  const double P = affine_flow_pressure_scale(block, 2);
  const std::array<double, 2> c{1.0, -2.0};
  EXPECT_NEAR(affine_flow_pressure(block, 2, kRho0, c), 0.5 * kRho0 * P, 1e-9 * kRho0 * P);
  for (int k = 0; k < 12; ++k) {
    const double th = 2.0 * std::numbers::pi * k / 12.0;
    const std::array<double, 2> s{c[0] + a * std::cos(th), c[1] + b * std::sin(th)};
    EXPECT_NEAR(affine_flow_pressure(block, 2, kRho0, s), 0.0, 1e-9 * kRho0 * P) << th;
  }
  const double dA_dt = A * A * (a * a - b * b) / (a * a + b * b);
  // dg/dt + g^2 along x (g = -A, so dg/dt = -dA/dt) and along y (g = A)
  const std::array<double, 2> accel_factor{-dA_dt + A * A, dA_dt + A * A};
  const double e = 1e-4;
  for (const std::array<double, 2> x : {std::array{1.3, -1.5}, std::array{0.6, -2.9}}) {
    for (int k = 0; k < 2; ++k) {
      std::array<double, 2> up = x, down = x;
      up[static_cast<std::size_t>(k)] += e;
      down[static_cast<std::size_t>(k)] -= e;
      const double dp = (affine_flow_pressure(block, 2, kRho0, up) -
                         affine_flow_pressure(block, 2, kRho0, down)) /
                        (2.0 * e);
      const double expected = accel_factor[static_cast<std::size_t>(k)] *
                              (x[static_cast<std::size_t>(k)] - c[static_cast<std::size_t>(k)]);
      EXPECT_NEAR(-dp / kRho0, expected, 1e-6 * A * A) << "axis " << k;
    }
  }
}

// 3D: the rates dg_k/dt = P / r_k^2 - g_k^2 keep tr G = 0, and p = 0 on the ellipsoid.
TEST(AffineFlowPressure, KeepsTheFlowIncompressible3D) {
  FluidBlock block;
  block.shape = "ellipsoid";
  block.min = {-1.0, -2.0, -0.4};
  block.max = {1.0, 2.0, 0.4};
  block.velocity = {0.0, 0.0, 0.0};
  const std::array<double, 3> g{1.0, 2.0, -3.0};
  const std::array<double, 3> r{1.0, 2.0, 0.4};
  block.velocity_gradient = {g[0], 0, 0, 0, g[1], 0, 0, 0, g[2]};
  const double P = affine_flow_pressure_scale(block, 3);
  double trace_rate = 0.0;
  for (std::size_t k = 0; k < 3; ++k)
    trace_rate += P / (r[k] * r[k]) - g[k] * g[k];
  EXPECT_NEAR(trace_rate, 0.0, 1e-13 * 14.0);
  for (const std::array<double, 3> s : {std::array{1.0, 0.0, 0.0}, std::array{0.0, -2.0, 0.0},
                                        std::array{0.6, 0.0, 0.32}, std::array{0.0, 1.2, 0.32}})
    EXPECT_NEAR(affine_flow_pressure(block, 3, kRho0, s), 0.0, 1e-9 * kRho0 * P);
}

}  // namespace
}  // namespace flume
