// The physical constants a scheme needs, resolved from the case file: fluid, equation of state,
// viscosity, turbulence model and body force. Plain data; equations take what they need from it.
#pragma once

#include "flume/core/vec.hpp"
#include "flume/equations/eos.hpp"

namespace flume {

// How the physical viscosity mu enters the momentum equation (methods.md, "viscous stress").
enum class ViscousTerm {
  bl24,  // through the velocity gradient, BL (22)-(25): sigma' = 2 mu d'
  w511,  // W (5.11): the double-summation Laplacian of W (5.4) in weak form, grad_h u from W (5.5)
  w57,   // Morris's Laplacian W (5.7)
};

// The Smagorinsky sub-grid model of LES-SPH, W (5.31)-(5.32) (subgrid_stress_w531.hpp).
struct Smagorinsky {
  bool on = false;
  double cs = 0.12;    // Smagorinsky constant C_s, -
  double ci = 0.0066;  // Yoshizawa's constant C_I of the isotropic part W (5.32), -
  double delta = 0.0;  // filter width Delta, m (W: the initial particle spacing)
};

template <int D>
struct Physics {
  Eos eos;
  double mu = 0.0;  // dynamic viscosity, Pa s
  ViscousTerm viscous = ViscousTerm::bl24;
  Smagorinsky les;        // LES-SPH's sub-grid stress, W (5.31)-(5.34)
  Vec<D> gravity;         // body force per unit mass, m/s^2
  double av_alpha = 0.0;  // artificial viscosity W (3.18), -
  double av_beta = 0.0;   // artificial viscosity W (3.18), -

  // A per-particle stress tensor enters the momentum equation through the BL (24) pair form:
  // the viscous stress of BL (23)-(24) or W (5.11), and/or LES's sub-grid stress.
  bool stress_term() const { return (mu > 0.0 && viscous != ViscousTerm::w57) || les.on; }
  // Morris's Laplacian W (5.7) is a pair term of its own (no stress tensor).
  bool morris_term() const { return mu > 0.0 && viscous == ViscousTerm::w57; }
};

}  // namespace flume
