// One structure of arrays holding every per-particle field, each declared once here with its
// unit. Owned ("real") particles come first, ghost copies (mirror walls, periodic images, later
// MPI halos) are appended after them, so a loop over real particles is a prefix [0, n_real).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "flume/core/vec.hpp"

namespace flume {

template <int D>
struct ParticleSet {
  using V = Vec<D>;
  using M = Mat<D>;

  // --- state: what defines a particle ---
  std::vector<std::int64_t> id;  // stable identity across re-sorting, -
  std::vector<V> x;              // position at the integer time level, m
  std::vector<V> v;              // velocity at the integer time level, m/s
  std::vector<double> m;         // mass, kg
  std::vector<double> rho;       // density, kg/m^3
  std::vector<double> h;         // smoothing length, m

  // --- derived in each step's sweeps ---
  std::vector<double> p;     // pressure (compression positive), Pa
  std::vector<M> grad_v;     // velocity gradient BL (22), (grad v)_{kl} = d v_k / d x_l, 1/s
  std::vector<M> stress;     // deviatoric (viscous) stress sigma' = 2 mu d', BL (23)-(24), Pa
  std::vector<V> a;          // acceleration, m/s^2
  std::vector<double> drho;  // density rate, kg/(m^3 s)

  // --- kernel and gradient corrections (CSPH, BL 4.3) ---
  std::vector<double> shepard;  // sum_b V_b W_b(x_a), the denominator of BL (53)-(54), -
  std::vector<V> gamma;         // gamma(x_a) of BL (57), 1/m
  std::vector<M> L;             // correction matrix L_a of BL (58), -

  // --- integrator state carried between steps (leap-frog staggered values) ---
  std::vector<V> v_half;  // staggered velocity v^{n+1/2} (after a step) / v^0 (at start), m/s

  std::size_t n_real = 0;  // owned particles: indices [0, n_real); ghosts follow

  std::size_t size() const { return x.size(); }

  // Applies f to every per-particle array, so that resizing and re-ordering can never forget
  // a field. Add a new field above and here, nowhere else.
  template <class F>
  void for_each_field(F&& f) {
    f(id);
    f(x);
    f(v);
    f(m);
    f(rho);
    f(h);
    f(p);
    f(grad_v);
    f(stress);
    f(a);
    f(drho);
    f(shepard);
    f(gamma);
    f(L);
    f(v_half);
  }

  void resize(std::size_t n) {
    for_each_field([n](auto& field) { field.resize(n); });
  }

  // Drops every ghost, keeping the real prefix.
  void drop_ghosts() { resize(n_real); }

  // Appends one real particle (only valid while there are no ghosts).
  void add_real(std::int64_t pid, const V& pos, const V& vel, double mass, double density,
                double smoothing) {
    const std::size_t i = size();
    resize(i + 1);
    id[i] = pid;
    x[i] = pos;
    v[i] = vel;
    v_half[i] = vel;
    m[i] = mass;
    rho[i] = density;
    h[i] = smoothing;
    n_real = i + 1;
  }

  // Re-orders the real particles so that new index k holds old index order[k]
  // (order is a permutation of [0, n_real)). Ghosts must have been dropped.
  void permute(const std::vector<std::size_t>& order) {
    for_each_field([&order](auto& field) {
      auto copy = field;
      for (std::size_t k = 0; k < order.size(); ++k)
        field[k] = copy[order[k]];
    });
  }
};

}  // namespace flume
