// The physical constants a scheme needs, resolved from the case file: fluid, equation of state,
// viscosity and body force. Plain data; equations take what they need from it.
#pragma once

#include "flume/core/vec.hpp"
#include "flume/equations/eos.hpp"

namespace flume {

template <int D>
struct Physics {
  Eos eos;
  double mu = 0.0;        // dynamic viscosity, Pa s (BL (22)-(25))
  Vec<D> gravity;         // body force per unit mass, m/s^2
  double av_alpha = 0.0;  // artificial viscosity W (3.18), -
  double av_beta = 0.0;   // artificial viscosity W (3.18), -
};

}  // namespace flume
