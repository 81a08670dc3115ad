// Particle clouds for the magnitude tests, and the lattice sums of a kernel that give the exact
// discrete answer of an SPH sum on a square lattice.
//
// On the square lattice of spacing dx with equal volumes V = dx^2, an interior particle a sees the
// same neighbours as every other, placed symmetrically; then for a kernel W(r, h):
//   sum_b V W_ab                        = s0                (s0 -> 1 as h/dx grows),
//   sum_b V grad_a W_ab                 = 0                 (odd in x_ab),
//   sum_b V (x_b - x_a) (x) grad_a W_ab = c I,  c = -(dx^2 / 2) sum_b r_ab W'(r_ab)   (2D),
// and the even (quadratic) part of a field drops out of any sum with grad W. So the uncorrected
// SPH gradient of a linear or quadratic field is exactly c times the true gradient at an
// interior particle, and the test can predict the code's number to round-off, and bound its
// distance from the continuum value by |c - 1| (the lattice consistency error of the kernel).
#pragma once

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "flume/core/particle_set.hpp"

namespace flume::test {

struct LatticeSums {
  double s0 = 0.0;  // dx^2 sum_k W(|k| dx, h)
  double c = 0.0;   // -(dx^2/2) sum_k r_k W'(r_k)
};

// The sums over the infinite square lattice, as the kernel formula gives them (every offset k
// with |k| dx < support h; the kernel is zero beyond).
template <class K>
LatticeSums lattice_sums(double dx, double h) {
  LatticeSums s;
  const int reach = static_cast<int>(std::ceil(K::support * h / dx)) + 1;
  for (int i = -reach; i <= reach; ++i)
    for (int j = -reach; j <= reach; ++j) {
      const double r = std::hypot(i * dx, j * dx);
      s.s0 += dx * dx * K::w(r, h);
      s.c -= 0.5 * dx * dx * r * K::dwdr(r, h);
    }
  return s;
}

// An n x n square lattice (n odd) of spacing dx centred on the origin, each coordinate moved by
// a uniform random amount in [-jitter dx, jitter dx] (jitter = 0: the perfect lattice, and the
// particle at the origin is the centre). Density rho(x) and velocity vel(x) at the particle's
// position, mass rho dx^2, so every volume m/rho is dx^2 (to one rounding).
template <class Rho, class Vel>
ParticleSet<2> square_lattice(int n, double dx, double h, double jitter, unsigned seed, Rho rho,
                              Vel vel) {
  ParticleSet<2> ps;
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> u(-jitter * dx, jitter * dx);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec<2> site{{(i - n / 2) * dx, (j - n / 2) * dx}};
      Vec<2> x = site;
      if (jitter > 0.0) x += Vec<2>{{u(gen), u(gen)}};
      const double r = rho(x);
      ps.add_real(i * n + j, x, vel(x), r * dx * dx, r, h);
    }
  return ps;
}

// Index of the particle at the lattice site (i, j) relative to the centre, for square_lattice.
inline std::size_t site(int n, int i, int j) {
  return static_cast<std::size_t>((i + n / 2) * n + (j + n / 2));
}

// The particles within `radius` of the origin (in the max norm): the interior of a lattice.
inline std::vector<std::size_t> within(const ParticleSet<2>& ps, double radius) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < ps.n_real; ++i)
    if (std::abs(ps.x[i][0]) <= radius && std::abs(ps.x[i][1]) <= radius) out.push_back(i);
  return out;
}

// The 2D Wendland C2 kernel written out from its formula (wendland_c2.hpp header comment), for
// the hand-computed cases: W = 7 / (4 pi h^2) (1 - q/2)^4 (2q + 1), dW/dr = -7 / (4 pi h^3) 5 q
// (1 - q/2)^3, q = r/h <= 2.
inline double wendland_w(double r, double h) {
  const double q = r / h, t = 1.0 - 0.5 * q;
  return q >= 2.0 ? 0.0 : 7.0 / (4.0 * std::numbers::pi * h * h) * t * t * t * t * (2.0 * q + 1.0);
}
inline double wendland_dwdr(double r, double h) {
  const double q = r / h, t = 1.0 - 0.5 * q;
  return q >= 2.0 ? 0.0 : -7.0 / (4.0 * std::numbers::pi * h * h * h) * 5.0 * q * t * t * t;
}
// grad_{x_a} W(x_a - x_b, h): BL's grad W_b(x_a).
inline Vec<2> wendland_grad(const Vec<2>& xa, const Vec<2>& xb, double h) {
  const Vec<2> d = xa - xb;
  const double r = norm(d);
  return r > 0.0 ? d * (wendland_dwdr(r, h) / r) : Vec<2>{};
}

}  // namespace flume::test
