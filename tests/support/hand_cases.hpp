// Small hand-checkable particle sets and reference formulas shared by the magnitude tests.
#pragma once

#include "flume/core/particle_set.hpp"
#include "flume/core/vec.hpp"

namespace flume::test {

// Three particles within 2h of each other for h of about 1.3 cm (Wendland C2), unequal masses,
// densities and velocities.
inline ParticleSet<2> triangle(double h) {
  ParticleSet<2> ps;
  ps.add_real(0, Vec<2>{{0.0, 0.0}}, Vec<2>{{0.3, -0.1}}, 0.10, 1010.0, h);
  ps.add_real(1, Vec<2>{{0.011, 0.002}}, Vec<2>{{-0.2, 0.4}}, 0.12, 995.0, h);
  ps.add_real(2, Vec<2>{{0.004, 0.012}}, Vec<2>{{0.1, 0.25}}, 0.09, 1003.0, h);
  return ps;
}

// sigma' = 2 mu (d - tr(d)/3 I), d = (G + G^T) / 2: BL (23)-(24) with the 3D deviator in 2D,
// written here apart from flume's own so the tests compare against an independent computation.
inline Mat<2> deviatoric(const Mat<2>& g, double mu) {
  Mat<2> d = (g + transpose(g)) * 0.5;
  const double third = (d(0, 0) + d(1, 1)) / 3.0;
  d(0, 0) -= third;
  d(1, 1) -= third;
  return d * (2.0 * mu);
}

}  // namespace flume::test
