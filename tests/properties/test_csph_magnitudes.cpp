// The magnitude of CSPH, BL section 4.3 (preset csph): the Shepard value S and gamma of BL (53),
// (57), the correction L of BL (58), the corrected velocity gradient BL (55) and its continuity
// rate, and the internal force BL (59) with pressure and viscous stress. Small clouds evaluated
// term by term from the formulas (exact to round-off), and linear pressure and quadratic velocity
// fields on a lattice, where CSPH must give -grad p / rho and div(sigma') / rho exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "flume/equations/correction.hpp"
#include "flume/schemes/registry.hpp"
#include "support/hand_cases.hpp"
#include "support/lattice.hpp"
#include "support/rates.hpp"

namespace flume {
namespace {

constexpr double kRho0 = 1000.0, kKappa = 1e5;

Physics<2> fluid(double gamma, double mu) {
  Physics<2> phys;
  phys.eos.rho0 = kRho0;
  phys.eos.gamma = gamma;
  phys.eos.kappa = kKappa;
  phys.mu = mu;
  return phys;
}

std::unique_ptr<Scheme<2>> csph(double gamma, double mu, KernelKind k = KernelKind::wendland_c2) {
  return make_scheme<2>(*preset_rows("csph"), k, fluid(gamma, mu));
}

// Every quantity of a corrected continuity scheme on a small cloud (one h, Wendland C2), term by
// term: for CSPH (mixed) from BL (53)-(59) with BL (57) corrected (erratum 2); for the Shepard
// correction the same with L = I; for the gradient correction BL (43)-(45) and the force of
// methods.md erratum 9. The reference the code is checked against.
struct CsphReference {
  std::vector<double> S, sigma_min, drho;
  std::vector<Vec<2>> gamma, accel;
  std::vector<Mat<2>> L, grad_v;

  CsphReference(const ParticleSet<2>& ps, double h, const Physics<2>& phys,
                Correction c = Correction::mixed) {
    const std::size_t n = ps.n_real;
    const auto V = [&](std::size_t b) { return ps.m[b] / ps.rho[b]; };
    const auto W = [&](std::size_t a, std::size_t b) {
      return test::wendland_w(norm(ps.x[a] - ps.x[b]), h);
    };
    const auto dW = [&](std::size_t a, std::size_t b) {
      return test::wendland_grad(ps.x[a], ps.x[b], h);
    };
    S.assign(n, 0.0);
    gamma.assign(n, {});
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = 0; b < n; ++b) {
        S[a] += V(b) * W(a, b);  // BL (53): S_a = sum_b V_b W_b(x_a), self term included
        gamma[a] += dW(a, b) * V(b);
      }
      gamma[a] = gamma[a] * (1.0 / S[a]);  // BL (57)
    }
    // grad W~_b(x_a) = [grad W_b(x_a) - W_b(x_a) gamma_a] / S_a (BL (57), erratum 2); the
    // gradient correction alone corrects grad W_b(x_a) itself.
    const auto gt = [&](std::size_t a, std::size_t b) {
      if (c == Correction::gradient) return dW(a, b);
      return (dW(a, b) - gamma[a] * W(a, b)) * (1.0 / S[a]);
    };
    for (std::size_t a = 0; a < n; ++a) {
      Mat<2> M, G;
      for (std::size_t b = 0; b < n; ++b) {
        M += outer(ps.x[b] - ps.x[a], gt(a, b)) * V(b);  // BL (58), differences (erratum 2)
        G += outer(ps.v[b] - ps.v[a], gt(a, b)) * V(b);  // BL (55)
      }
      // The smallest singular value of a 2 x 2 matrix [[a, b], [c, d]], in closed form:
      // (sqrt((a + d)^2 + (c - b)^2) - sqrt((a - d)^2 + (b + c)^2)) / 2 (independent of
      // flume's route through the eigenvalues of M^T M).
      const double a0 = M(0, 0), b0 = M(0, 1), c0 = M(1, 0), d0 = M(1, 1);
      sigma_min.push_back(0.5 * (std::hypot(a0 + d0, c0 - b0) - std::hypot(a0 - d0, b0 + c0)));
      // L_a = M_a^{-T}; where M_a cannot be inverted usefully (sigma_min < 0.05) flume uses
      // L_a = I (corrected_velocity_gradient.hpp).
      const bool ok = c != Correction::shepard && sigma_min.back() >= 0.05;
      L.push_back(ok ? transpose(inverse(M)) : Mat<2>::identity());
      grad_v.push_back(ok ? G * inverse(M) : G);
    }
    for (std::size_t a = 0; a < n; ++a) {
      double div = 0.0;
      Vec<2> acc;
      for (std::size_t b = 0; b < n; ++b) {
        div += V(b) * dot(ps.v_half[b] - ps.v_half[a], L[a] * gt(a, b));
        // BL (59), compression positive: a_a = sum_b m_b / (rho_a rho_b) (p_b I - sigma'_b)
        // L_b grad W~_a(x_b); b = a is part of the sum.
        const auto stress = [&](std::size_t d) {
          const double pd = phys.eos.kappa * (std::pow(ps.rho[d] / kRho0, phys.eos.gamma) - 1.0);
          return Mat<2>::identity() * pd - test::deviatoric(grad_v[d], phys.mu);
        };
        const double mrr = ps.m[b] / (ps.rho[a] * ps.rho[b]);
        if (c == Correction::gradient) {
          // Erratum 9, compression positive: sum_b m_b / (rho_a rho_b) (sigma_a L_a +
          // sigma_b L_b) grad W_a(x_b) with sigma = p I - sigma'; the b = a term is zero.
          acc += (stress(a) * L[a] + stress(b) * L[b]) * dW(b, a) * mrr;
        } else {
          acc += stress(b) * (L[b] * gt(b, a)) * mrr;
        }
      }
      drho.push_back(-ps.rho[a] * div);
      accel.push_back(acc);
    }
  }
};

// A 3 x 3 patch, spacing 1 cm, each site moved by < 1 mm, h = 1.05 cm, and a tenth particle
// off a corner that sees that corner only (the next nearest are 2.2 cm > 2h away): its M is of
// rank one (sigma_min ~0, L = I), the patch's are usable (sigma_min 0.40-0.89, the corners'
// and edges' ~0.4 and the centre's 0.89), so both branches of L and a non-symmetric M (the
// patch is irregular) are exercised.
ParticleSet<2> patch() {
  const double off[9][2] = {{0.6, -0.4}, {-0.3, 0.8},  {0.2, 0.5}, {-0.7, 0.1}, {0.4, -0.6},
                            {0.9, 0.3},  {-0.2, -0.8}, {0.5, 0.2}, {-0.6, 0.7}};
  const double rho[9] = {1004, 998, 1001, 997, 1006, 1002, 999, 1003, 995};
  ParticleSet<2> ps;
  for (int k = 0; k < 9; ++k) {
    const Vec<2> x{{(k / 3 - 1) * 0.01 + off[k][0] * 1e-3, (k % 3 - 1) * 0.01 + off[k][1] * 1e-3}};
    const Vec<2> v{{0.3 * std::sin(k + 1.0), 0.2 * std::cos(2.0 * k)}};
    ps.add_real(k, x, v, 0.1 * (1.0 + 0.01 * k), rho[k], 0.0105);
  }
  ps.add_real(9, Vec<2>{{-0.0203, -0.0198}}, Vec<2>{{0.1, -0.25}}, 0.1, 1001.0, 0.0105);
  return ps;
}

// Round-off: each quantity is a sum of <= 9 terms, each a product of a few factors, then (for
// L, grad v) a 2 x 2 inverse with sigma_min >= 0.39 and (for a) another sum; the pressures carry up
// to ~8 ulp / 0.006 (the smallest |rho/rho0 - 1| here gives X - 1 ~ 0.02) ~ 3e-13 relative.
// 1e-11 of the sum of the terms' sizes, estimated by scale * (1 + |value|), is ample; a wrong
// factor, a swapped index or a sign changes these by percent or more.
void expect_close(double got, double want, double scale, const char* what, std::size_t a) {
  EXPECT_NEAR(got, want, 1e-11 * (scale + std::abs(want))) << what << " of particle " << a;
}

void check_against_reference(ParticleSet<2> ps, double h, double mu,
                             Correction c = Correction::mixed) {
  const auto phys = fluid(7.0, mu);
  const CsphReference ref(ps, h, phys, c);
  const char* names[] = {"gradient", "shepard", "mixed"};
  test::compute_rates(*make_scheme<2>(SchemeRows{"continuity", "bl20", names[static_cast<int>(c)]},
                                      KernelKind::wendland_c2, phys),
                      ps);
  for (std::size_t a = 0; a < ps.n_real; ++a) {
    ASSERT_TRUE(ref.sigma_min[a] < 0.04 || ref.sigma_min[a] > 0.06)
        << "ambiguous set-up at particle " << a;
    if (c != Correction::gradient) expect_close(ps.shepard[a], ref.S[a], 0.0, "S", a);
    for (int k = 0; k < 2; ++k) {
      if (c != Correction::gradient)
        expect_close(ps.gamma[a][k], ref.gamma[a][k], norm(ref.gamma[a]), "gamma", a);
      for (int l = 0; l < 2; ++l) {
        expect_close(ps.L[a](k, l), ref.L[a](k, l), 1.0, "L", a);
        expect_close(ps.grad_v[a](k, l), ref.grad_v[a](k, l), 100.0, "grad v", a);
      }
      // Forces are ~ p / (rho h) ~ 1e3 m/s^2 here; the terms are of that size.
      expect_close(ps.a[a][k], ref.accel[a][k], 1e3, "a", a);
    }
    expect_close(ps.drho[a], ref.drho[a], 1e4, "drho", a);
  }
}

TEST(CsphMagnitude, ShepardGammaGradientAndForceOfThreeParticlesByHand) {
  check_against_reference(test::triangle(0.013), 0.013, 0.0);  // sigma_min 0.21-0.23: L used
  // Hand values for the record, from the Wendland C2 formula (python, independent of flume):
  // S = 0.50106, 0.55864, 0.45323; gamma_0 = (57.271, 37.068) 1/m.
  auto ps = test::triangle(0.013);
  test::compute_rates(*csph(7.0, 0.0), ps);
  EXPECT_NEAR(ps.shepard[0], 0.5010559773985, 1e-12);
  EXPECT_NEAR(ps.shepard[1], 0.5586407223905, 1e-12);
  EXPECT_NEAR(ps.gamma[0][0], 57.27103377283, 1e-9);
  EXPECT_NEAR(ps.gamma[0][1], 37.06797414407, 1e-9);
  EXPECT_NEAR(ps.gamma[2][1], -73.35849504703, 1e-9);
}

TEST(CsphMagnitude, ViscousForceOfThreeParticlesByHand) {
  check_against_reference(test::triangle(0.013), 0.013, 0.5);
}

TEST(CsphMagnitude, IrregularPatchWithBothBranchesOfLByHand) {
  check_against_reference(patch(), 0.0105, 0.0);
  check_against_reference(patch(), 0.0105, 0.5);
}

// The other corrections of the continuity schemes on the same patch: the gradient correction
// BL (42)-(45) with the force of erratum 9 (its L_a from the uncorrected M_a: the lone tenth
// particle falls back), and the Shepard correction BL (53), (57) (L = I everywhere).
TEST(CorrectionMagnitude, GradientCorrectionOfAnIrregularPatchByHand) {
  check_against_reference(patch(), 0.0105, 0.0, Correction::gradient);
  check_against_reference(patch(), 0.0105, 0.5, Correction::gradient);
  check_against_reference(test::triangle(0.013), 0.013, 0.5, Correction::gradient);
}

TEST(CorrectionMagnitude, ShepardCorrectionOfAnIrregularPatchByHand) {
  check_against_reference(patch(), 0.0105, 0.0, Correction::shepard);
  check_against_reference(patch(), 0.0105, 0.5, Correction::shepard);
}

// ---- Fields with a known answer on a lattice and a jittered cloud ----

constexpr double kDx = 0.01, kH = 1.3 * kDx;
constexpr int kN = 25;
// Two kernel supports (2 x 3.9 dx for the quintic) from the edge: a particle whose neighbours'
// neighbours all sit on the full lattice.
constexpr double kInterior = (kN / 2) * kDx - 8.0 * kDx;

// p = p0 + G . x through the linear (gamma = 1) Tait EOS: rho = rho0 (1 + p / kappa).
const Vec<2> kG{{3.0e3, -2.0e3}};  // Pa/m
double rho_of(const Vec<2>& x) {
  return kRho0 * (1.0 + (50.0 + dot(kG, x)) / kKappa);
}
Vec<2> at_rest(const Vec<2>&) {
  return {};
}

TEST(CsphMagnitude, ForceOfALinearPressureIsExactOnALattice) {
  // Interior of the lattice: S_b = s0, gamma_b = 0, M_b = (c/s0) I, L_b = (s0/c) I, so BL (59)
  // gives a_a = -(1/(c rho_a)) sum_b V p_b grad_a W_ab = -G / rho_a exactly: the correction
  // removes the lattice error c - 1 that BL (20) keeps (up to 2.6 %). Round-off: terms of size
  // p V |grad W| / c ~ 1e3 Pa/m against |G| = 3.6e3 Pa/m: 1e-12 relative to |G| / rho.
  for (const auto kernel : kernel_kinds) {
    auto ps = test::square_lattice(kN, kDx, kH, 0.0, 1, rho_of, at_rest);
    test::compute_rates(*csph(1.0, 0.0, kernel), ps);
    for (const auto i : test::within(ps, kInterior))
      for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(ps.a[i][k], -kG[k] / ps.rho[i], 1e-12 * norm(kG) / kRho0)
            << kernel_name(kernel) << " " << i;
  }
}

struct JitterError {
  double uniform = 0.0;  // max_a |a_a| rho_a h / P for a uniform pressure P (zeroth moment)
  double linear = 0.0;   // max_a |a_a rho_a + G| / |G| for p = G . (x - x_a) (first moment)
};

// The two consistency errors of a pressure force at the particles within 2 dx of the centre of a
// cloud jittered by up to `jitter` dx: the force of a uniform pressure (which should vanish) and,
// for each such particle a, of the pressure G . (x - x_a), zero at a (which should be -G / rho_a).
// gamma = 1: rho = rho0 (1 + p / kappa), masses rho dx^2, so the volumes are dx^2 in every run.
JitterError pressure_force_error(const std::string& preset, double jitter) {
  const auto scheme =
      make_scheme<2>(*preset_rows(preset), KernelKind::cubic_spline, fluid(1.0, 0.0));
  const auto cloud = [&](auto pressure) {
    return test::square_lattice(
        kN, kDx, kH, jitter, 5,
        [&](const Vec<2>& s) { return kRho0 * (1.0 + pressure(s) / kKappa); }, at_rest);
  };
  JitterError e;
  const double P = 100.0;
  auto ps = cloud([&](const Vec<2>&) { return P; });
  test::compute_rates(*scheme, ps);
  const auto centre = test::within(ps, 2.0 * kDx + jitter * kDx);
  for (const auto a : centre)
    e.uniform = std::max(e.uniform, norm(ps.a[a]) * ps.rho[a] * kH / P);
  for (const auto a : centre) {
    const Vec<2> xa = ps.x[a];
    auto lin = cloud([&](const Vec<2>& x) { return dot(kG, x - xa); });
    test::compute_rates(*scheme, lin);
    e.linear = std::max(e.linear, norm(lin.a[a] * lin.rho[a] + kG) / norm(kG));
  }
  return e;
}

TEST(CsphMagnitude, ForceOfALinearPressureOnAJitteredCloud) {
  // BL (59) is not exact for a linear pressure on an irregular cloud, unlike BL (55) for a linear
  // velocity (test_density_magnitudes.cpp): a_a rho_a = sum_b V_b p_b L_b grad W~_a(x_b) applies
  // the neighbours' corrections L_b, S_b, gamma_b (it is the variational adjoint of BL (55), not
  // a corrected gradient at a), so neither its zeroth moment sum_b V_b L_b grad W~_a(x_b) nor
  // its first moment + I vanish once L, S, gamma vary from particle to particle; both errors are
  // first order in the jitter. Measured (cubic spline, h = 1.3 dx, 25 particles around the
  // centre) at jitter 0.05, 0.1, 0.2 dx: first moment 4.4 %, 9.1 %, 19 % of |G|; zeroth moment
  // 0.10, 0.20, 0.36 P / (rho h). (BL (20) on the same clouds: 3.8 %, 6.9 %, 13 % and 0.13,
  // 0.25, 0.42: CSPH's force is no more accurate there; its gain is on a lattice, where it
  // removes the c - 1 that BL (20) keeps, and in the exactness of its velocity gradient.)
  // Bounds: 13 % and 0.3 at 0.1 dx, and first order: ratio 1.8 to 2.3 from 0.05 to 0.1 dx.
  const auto fine = pressure_force_error("csph", 0.05);
  const auto coarse = pressure_force_error("csph", 0.1);
  EXPECT_LT(coarse.linear, 0.13);
  EXPECT_LT(coarse.uniform, 0.3);
  EXPECT_GT(coarse.linear / fine.linear, 1.8);
  EXPECT_LT(coarse.linear / fine.linear, 2.3);
  EXPECT_GT(coarse.uniform / fine.uniform, 1.8);
  EXPECT_LT(coarse.uniform / fine.uniform, 2.3);
}

// u = (x^2 + 0.5 xy - 0.3 y^2, 0.2 x^2 - 0.7 xy + 0.4 y^2) m/s (x in m): compressible, so the
// deviator's 1/3 matters. div sigma' = mu (lap u + grad(div u) / 3) with lap u = (1.4, 1.2),
// grad div u = (1.3, 1.3): (11/6, 49/30) mu. (With a 2D deviator, 1/2, it would be (1.4, 1.2) mu.)
Vec<2> quadratic(const Vec<2>& x) {
  const double X = x[0], Y = x[1];
  return Vec<2>{{X * X + 0.5 * X * Y - 0.3 * Y * Y, 0.2 * X * X - 0.7 * X * Y + 0.4 * Y * Y}};
}
const Vec<2> kDivStressOverMu{{11.0 / 6.0, 49.0 / 30.0}};  // 1/(m s)

TEST(CsphMagnitude, ViscousForceOfAQuadraticFieldIsExactOnALattice) {
  // Interior of the lattice: BL (55) is exact for the quadratic field (its even part drops out,
  // the linear part is corrected by L), so sigma'_b is the exact linear stress field, and BL (59)
  // with L_b = (s0/c) I, grad W~ = grad W / s0 gives a_a = (1/(c rho)) sum_b V sigma'_b
  // grad_a W_ab = div sigma' / rho exactly (the uncorrected continuity scheme gives c^2 times
  // it, test_viscosity_magnitudes.cpp). rho = rho0, so p = 0. Round-off: terms of size
  // V |sigma'| |grad W| ~ mu |grad u| / h ~ mu / h * 0.1, against mu * 2: 1e-11 relative.
  const double mu = 0.5;
  for (const auto kernel : kernel_kinds) {
    auto ps = test::square_lattice(
        kN, kDx, kH, 0.0, 1, [](const Vec<2>&) { return kRho0; }, quadratic);
    test::compute_rates(*csph(7.0, mu, kernel), ps);
    const Vec<2> want = kDivStressOverMu * (mu / kRho0);
    for (const auto i : test::within(ps, kInterior))
      for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(ps.a[i][k], want[k], 1e-11 * norm(want)) << kernel_name(kernel) << " " << i;
  }
}

}  // namespace
}  // namespace flume
