// The magnitude of the thesis's viscous terms and of LES-SPH's sub-grid stress, each against an
// independent computation: Morris's Laplacian W (5.7) and W (5.11)'s double-summation form by
// hand on a pair and on quadratic fields on a lattice, whose discrete values are known exactly;
// the Smagorinsky-Yoshizawa stress W (5.31)-(5.32) by hand on a simple shear and through the
// momentum equation on a pair. (BL (22)-(24): test_viscosity_magnitudes.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "flume/equations/subgrid_stress_w531.hpp"
#include "flume/kernels/kernel.hpp"
#include "flume/schemes/registry.hpp"
#include "support/hand_cases.hpp"
#include "support/lattice.hpp"
#include "support/rates.hpp"

namespace flume {
namespace {

constexpr double kRho0 = 1000.0, kC0 = 10.0, kH = 0.013;

Physics<2> water(double mu, ViscousTerm term) {
  Physics<2> phys;
  phys.eos.rho0 = kRho0;
  phys.eos.gamma = 7.0;
  phys.eos.kappa = kRho0 * kC0 * kC0 / 7.0;
  phys.mu = mu;
  phys.viscous = term;
  return phys;
}

double pressure(double rho) {
  return kRho0 * kC0 * kC0 / 7.0 * (std::pow(rho / kRho0, 7.0) - 1.0);
}

// Two particles 0.76 h apart, unequal masses, densities and velocities.
ParticleSet<2> pair() {
  ParticleSet<2> ps;
  ps.add_real(0, Vec<2>{{0.0, 0.0}}, Vec<2>{{0.5, 0.1}}, 0.10, 1002.0, kH);
  ps.add_real(1, Vec<2>{{0.009, 0.004}}, Vec<2>{{-0.3, 0.2}}, 0.12, 998.0, kH);
  return ps;
}

// BL (20) = W (3.80) without Pi, from a to b.
Vec<2> pressure_part(const ParticleSet<2>& ps, std::size_t a, std::size_t b) {
  return test::wendland_grad(ps.x[a], ps.x[b], kH) *
         (-ps.m[b] / (ps.rho[a] * ps.rho[b]) * (pressure(ps.rho[a]) + pressure(ps.rho[b])));
}

// BL (22) = W (5.5) of each particle of the pair, by hand.
std::array<Mat<2>, 2> pair_gradients(const ParticleSet<2>& x) {
  const Vec<2> g01 = test::wendland_grad(x.x[0], x.x[1], kH);
  return {outer(x.v[1] - x.v[0], g01) * (x.m[1] / x.rho[1]),
          outer(x.v[0] - x.v[1], g01 * -1.0) * (x.m[0] / x.rho[0])};
}

std::unique_ptr<Scheme<2>> scheme(const std::string& preset, const Physics<2>& phys) {
  return make_scheme<2>(*preset_rows(preset), KernelKind::wendland_c2, phys);
}

TEST(MorrisViscosityW57, PairByHand) {
  const double mu = 0.8;
  for (const std::string preset : {"continuity", "wsph", "standard"}) {
    auto ps = pair();
    const auto x = ps;
    test::compute_rates(*scheme(preset, water(mu, ViscousTerm::w57)), ps);
    for (std::size_t a = 0; a < 2; ++a) {
      const std::size_t b = 1 - a;
      // (mu / rho_a) lap u_a, lap u_a = 2 omega_b u_ab (x_ab . grad_a W) / (r^2 + eta^2),
      // omega_b = m_b / rho_b, eta^2 = 0.01 h^2.
      const Vec<2> xab = x.x[a] - x.x[b];
      const double s = 2.0 * mu / x.rho[a] * (x.m[b] / x.rho[b]) *
                       dot(xab, test::wendland_grad(x.x[a], x.x[b], kH)) /
                       (norm2(xab) + 0.01 * kH * kH);
      const Vec<2> visc = (x.v[a] - x.v[b]) * s;
      // The summation density of "standard" changes rho (and p); compare with its own.
      const Vec<2> p_part = preset == "standard" ? ps.a[a] - visc : pressure_part(x, a, b);
      const Vec<2> want = p_part + visc;
      // Round-off: 1e-12 of the parts (test_viscosity_magnitudes.cpp says why).
      const double tol = 1e-12 * (norm(p_part) + norm(visc));
      EXPECT_NEAR(ps.a[a][0], want[0], tol) << preset << a;
      EXPECT_NEAR(ps.a[a][1], want[1], tol) << preset << a;
      if (preset != "standard") {
        EXPECT_GT(norm(visc), 0.2 * norm(want)) << preset;
      }
    }
    // The pair force is antisymmetric: m_0 a_0 + m_1 a_1 = 0 to round-off.
    const Vec<2> total = ps.a[0] * x.m[0] + ps.a[1] * x.m[1];
    EXPECT_LT(norm(total), 1e-13 * x.m[0] * norm(ps.a[0])) << preset;
  }
}

TEST(NavierStokesViscosityW511, PairByHand) {
  const double mu = 0.8;
  auto ps = pair();
  const auto x = ps;
  test::compute_rates(*scheme("continuity", water(mu, ViscousTerm::w511)), ps);
  const auto G = pair_gradients(x);
  // T = mu G + (lambda + mu) tr(G) I, lambda = -2 mu / 3 (Stokes): W (5.11)'s two sums.
  auto T = [&](const Mat<2>& g) {
    Mat<2> t = g * mu;
    const double bulk = (mu / 3.0) * (g(0, 0) + g(1, 1));
    t(0, 0) += bulk;
    t(1, 1) += bulk;
    return t;
  };
  for (std::size_t a = 0; a < 2; ++a) {
    const std::size_t b = 1 - a;
    const Vec<2> visc = (T(G[a]) + T(G[b])) * test::wendland_grad(x.x[a], x.x[b], kH) *
                        (x.m[b] / (x.rho[a] * x.rho[b]));
    const Vec<2> want = pressure_part(x, a, b) + visc;
    const double tol = 1e-12 * (norm(pressure_part(x, a, b)) + norm(visc));
    EXPECT_NEAR(ps.a[a][0], want[0], tol) << a;
    EXPECT_NEAR(ps.a[a][1], want[1], tol) << a;
    EXPECT_GT(norm(visc), 0.2 * norm(want));
  }
}

// ---- Quadratic fields on a lattice ----

constexpr double kDx = 0.01, kHl = 1.3 * kDx;
constexpr int kN = 25;
constexpr double kInterior = (kN / 2) * kDx - 8.0 * kDx;  // two quintic supports from the edge

// u = (x^2 + 0.5 xy - 0.3 y^2, 0.2 x^2 - 0.7 xy + 0.4 y^2): lap u = (1.4, 1.2), grad div u =
// (2 - 0.7, 0.5 + 0.8) = (1.3, 1.3).
Vec<2> quadratic(const Vec<2>& x) {
  const double X = x[0], Y = x[1];
  return Vec<2>{{X * X + 0.5 * X * Y - 0.3 * Y * Y, 0.2 * X * X - 0.7 * X * Y + 0.4 * Y * Y}};
}
const Vec<2> kLaplacian{{1.4, 1.2}};
const Vec<2> kGradDiv{{1.3, 1.3}};

// The continuity preset on the lattice (masses rho0 dx^2, rho = rho0: p = 0, volumes dx^2).
template <class Field>
ParticleSet<2> lattice_rates(KernelKind kernel, const Physics<2>& phys, Field field) {
  auto ps = test::square_lattice(
      kN, kDx, kHl, 0.0, 1, [](const Vec<2>&) { return kRho0; }, field);
  test::compute_rates(*make_scheme<2>(*preset_rows("continuity"), kernel, phys), ps);
  return ps;
}

// Morris's lattice factor: -(dx^2/2) sum_k r_k^3 W'(r_k) / (r_k^2 + eta^2), the lattice sum of
// W (5.7) for u = (y^2, 0) divided by 2 (the square lattice's sum of y^2 f(r) is half its sum
// of r^2 f(r)); 1 in the continuum without eta.
template <class K>
double morris_lattice_factor(double dx, double h) {
  double c = 0.0;
  const int reach = static_cast<int>(std::ceil(K::support * h / dx)) + 1;
  for (int i = -reach; i <= reach; ++i)
    for (int j = -reach; j <= reach; ++j) {
      const double r = std::hypot(i * dx, j * dx);
      c -= 0.5 * dx * dx * r * r * r * K::dwdr(r, h) / (r * r + 0.01 * h * h);
    }
  return c;
}

TEST(MorrisViscosityW57, LaplacianOfAQuadraticFieldOnALattice) {
  // In the interior the odd terms of u_ij cancel and W (5.7) gives m lap u exactly, m the
  // lattice factor above (round-off 1e-10 of it); against the continuum lap u: |m - 1| is
  // 0.02 % (cubic), 0.7 % (quintic), 0.9 % (Gaussian), 3.7 % (Wendland C2) at h = 1.3 dx;
  // bound 5 % of |lap u|. Halving the term, or a sign, is off by 50 % or 200 %.
  const double mu = 0.5;
  const Vec<2> exact = kLaplacian * (mu / kRho0);
  for (const auto kernel : kernel_kinds) {
    const double m =
        with_kernel<2>(kernel, [](auto k) { return morris_lattice_factor<decltype(k)>(kDx, kHl); });
    const auto ps = lattice_rates(kernel, water(mu, ViscousTerm::w57), quadratic);
    for (const auto i : test::within(ps, kInterior))
      for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(ps.a[i][k], m * exact[k], 1e-10 * norm(exact)) << kernel_name(kernel);
        EXPECT_NEAR(ps.a[i][k], exact[k], 0.05 * norm(exact)) << kernel_name(kernel);
      }
  }
}

TEST(NavierStokesViscosityW511, ForceOfAQuadraticFieldOnALattice) {
  // W (5.5) gives c times the exact (linear) gradient in the interior (c the lattice factor of
  // support/lattice.hpp), T is linear in it, and the outer sum multiplies by c again: the force
  // is c^2 (mu lap u + (mu/3) grad div u) / rho0 exactly (round-off 1e-10). Against the
  // continuum: |c^2 - 1| = 2.1 % (cubic), 5.1 % (Wendland C2), < 0.3 % (quintic, Gaussian); bound
  // 6 %. Dropping the (lambda + mu) term changes the force by 30 %, lambda = -mu/3 by 27 %.
  const double mu = 0.5;
  const Vec<2> exact = (kLaplacian + kGradDiv * (1.0 / 3.0)) * (mu / kRho0);
  for (const auto kernel : kernel_kinds) {
    const double c =
        with_kernel<2>(kernel, [](auto k) { return test::lattice_sums<decltype(k)>(kDx, kHl).c; });
    const auto ps = lattice_rates(kernel, water(mu, ViscousTerm::w511), quadratic);
    for (const auto i : test::within(ps, kInterior))
      for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(ps.a[i][k], c * c * exact[k], 1e-10 * norm(exact)) << kernel_name(kernel);
        EXPECT_NEAR(ps.a[i][k], exact[k], 0.06 * norm(exact)) << kernel_name(kernel);
      }
  }
}

// ---- LES-SPH, W (5.31)-(5.34) ----

TEST(SubgridStressW531, SimpleShearByHand) {
  // u = (gamma y, 0): S = [[0, g/2], [g/2, 0]], |S| = sqrt(2 S:S) = g, nu_r = (Cs Delta)^2 g;
  // -tau_xy = 2 rho nu_r g/2 = rho (Cs Delta)^2 g^2 and -tau_xx = -tau_yy = -(2/3) C_I rho
  // Delta^2 g^2 (tr S = 0). Round-off only.
  const double g = 40.0, rho = 1010.0;
  Smagorinsky les;
  les.on = true;
  les.delta = 0.02;
  Mat<2> G{};
  G(0, 1) = g;
  const auto s = subgrid_stress_w531(G, rho, les);
  const double cd2 = 0.12 * 0.02 * 0.12 * 0.02;
  EXPECT_NEAR(s.nu_r, cd2 * g, 1e-15 * cd2 * g);
  EXPECT_NEAR(s.minus_tau(0, 1), rho * cd2 * g * g, 1e-13 * rho * cd2 * g * g);
  EXPECT_NEAR(s.minus_tau(1, 0), rho * cd2 * g * g, 1e-13 * rho * cd2 * g * g);
  const double iso = -(2.0 / 3.0) * 0.0066 * rho * 0.02 * 0.02 * g * g;
  EXPECT_NEAR(s.minus_tau(0, 0), iso, 1e-13 * std::abs(iso));
  EXPECT_NEAR(s.minus_tau(1, 1), iso, 1e-13 * std::abs(iso));
}

TEST(SubgridStressW531, CompressionTakesTheDeviatorAndTheIsotropicPart) {
  // u = (a x, b y): S = diag(a, b), |S| = sqrt(2 (a^2 + b^2)), S' = S - (a + b)/3 I.
  const double a = 30.0, b = -10.0, rho = 990.0;
  Smagorinsky les;
  les.on = true;
  les.delta = 0.01;
  les.cs = 0.2;
  les.ci = 0.01;
  Mat<2> G{};
  G(0, 0) = a;
  G(1, 1) = b;
  const auto s = subgrid_stress_w531(G, rho, les);
  const double abs_s = std::sqrt(2.0 * (a * a + b * b));
  const double nu = 0.2 * 0.01 * 0.2 * 0.01 * abs_s;
  const double iso = (2.0 / 3.0) * 0.01 * rho * 0.01 * 0.01 * abs_s * abs_s;
  EXPECT_NEAR(s.nu_r, nu, 1e-15 * nu);
  EXPECT_NEAR(s.minus_tau(0, 0), 2.0 * rho * nu * (a - (a + b) / 3.0) - iso, 1e-12);
  EXPECT_NEAR(s.minus_tau(1, 1), 2.0 * rho * nu * (b - (a + b) / 3.0) - iso, 1e-12);
  EXPECT_EQ(s.minus_tau(0, 1), 0.0);
}

TEST(LesSph, PairByHand) {
  // les-sph on the pair: a_a = pressure + m_b/(rho_a rho_b) ((sigma - tau)_a + (sigma - tau)_b)
  // grad_a W with sigma = 2 mu d' (BL (23), W (5.30)) and -tau of W (5.31)-(5.32) written here.
  for (const double mu : {0.0, 0.3}) {
    auto phys = water(mu, ViscousTerm::bl24);
    phys.les.on = true;
    phys.les.delta = 0.02;
    auto ps = pair();
    const auto x = ps;
    test::compute_rates(*scheme("les-sph", phys), ps);
    const auto G = pair_gradients(x);
    auto minus_tau = [&](const Mat<2>& g, double rho) {
      const Mat<2> S = (g + transpose(g)) * 0.5;
      const double ss = S(0, 0) * S(0, 0) + 2.0 * S(0, 1) * S(0, 1) + S(1, 1) * S(1, 1);
      const double abs_s = std::sqrt(2.0 * ss);
      const double nu_r = 0.12 * 0.02 * 0.12 * 0.02 * abs_s;
      Mat<2> dev = S;
      const double third = (S(0, 0) + S(1, 1)) / 3.0;
      dev(0, 0) -= third;
      dev(1, 1) -= third;
      Mat<2> t = dev * (2.0 * rho * nu_r);
      const double iso = (2.0 / 3.0) * 0.0066 * rho * 0.02 * 0.02 * abs_s * abs_s;
      t(0, 0) -= iso;
      t(1, 1) -= iso;
      return t;
    };
    for (std::size_t a = 0; a < 2; ++a) {
      const std::size_t b = 1 - a;
      const Mat<2> stress_a = test::deviatoric(G[a], mu) + minus_tau(G[a], x.rho[a]);
      const Mat<2> stress_b = test::deviatoric(G[b], mu) + minus_tau(G[b], x.rho[b]);
      const Vec<2> sgs = (minus_tau(G[a], x.rho[a]) + minus_tau(G[b], x.rho[b])) *
                         test::wendland_grad(x.x[a], x.x[b], kH) * (x.m[b] / (x.rho[a] * x.rho[b]));
      const Vec<2> visc = (stress_a + stress_b) * test::wendland_grad(x.x[a], x.x[b], kH) *
                          (x.m[b] / (x.rho[a] * x.rho[b]));
      const Vec<2> want = pressure_part(x, a, b) + visc;
      const double tol = 1e-12 * (norm(pressure_part(x, a, b)) + norm(visc));
      EXPECT_NEAR(ps.a[a][0], want[0], tol) << mu << a;
      EXPECT_NEAR(ps.a[a][1], want[1], tol) << mu << a;
      // The sub-grid part is a visible share (a wrong constant or sign moves the total).
      EXPECT_GT(norm(sgs), 0.05 * norm(want)) << mu << a;
      // The eddy viscosity of the time step.
      const Mat<2> S = (G[a] + transpose(G[a])) * 0.5;
      const double abs_s =
          std::sqrt(2.0 * (S(0, 0) * S(0, 0) + 2.0 * S(0, 1) * S(0, 1) + S(1, 1) * S(1, 1)));
      EXPECT_NEAR(ps.nu_t[a], 0.12 * 0.02 * 0.12 * 0.02 * abs_s, 1e-12 * abs_s) << a;
    }
  }
}

}  // namespace
}  // namespace flume
