// The geometry of one interacting pair (i, j), computed once by the sweep driver and handed to
// every equation of a group: no equation recomputes r, W or grad W. The driver hands each pair
// over once, and the equation gives both particles their share (docs/adding_an_equation.md).
// The driver evaluates blocks of candidates j without a branch, so it also hands over
// candidates beyond the support: for those in = 0, w = 0 and gradw = 0. Every term of an SPH
// sum carries W or grad W and so vanishes there; a term that carries neither is multiplied by in.
#pragma once

#include <cstddef>

#include "flume/core/vec.hpp"

namespace flume {

template <int D>
struct Pair {
  Vec<D> xij;       // x_i - x_j, m
  double r = 0.0;   // |x_i - x_j|, m
  double h = 0.0;   // pair smoothing length (h_i + h_j)/2 (W, text after (3.46)), m
  double w = 0.0;   // W(r, h), 1/m^D
  Vec<D> gradw;     // grad_{x_i} W(x_i - x_j, h) = BL's grad W_j(x_i) = -grad W_i(x_j), 1/m^(D+1)
  double in = 1.0;  // 1 if r < support h (a pair), 0 for a candidate beyond the support, -
};

}  // namespace flume
