// One structure of arrays holding every per-particle field, each declared once here with its
// unit. Owned ("real") particles come first, ghost copies (mirror walls, periodic images, later
// MPI halos) are appended after them, so a loop over real particles is a prefix [0, n_real).
// State fields define a particle and are carried between steps (and re-ordered when particles
// are sorted); derived fields are recomputed by every step before they are read. Optional fields
// are allocated only when the scheme uses them (Scheme::fields()).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "flume/core/vec.hpp"

namespace flume {

// The optional per-particle fields, as bits of ParticleSet::optional.
enum OptionalField : unsigned {
  kFieldGradV = 1u << 0,          // grad_v
  kFieldStress = 1u << 1,         // stress
  kFieldDrho = 1u << 2,           // drho
  kFieldShepard = 1u << 3,        // shepard, gamma
  kFieldL = 1u << 4,              // L, bl41_deviation
  kFieldEnergy = 1u << 5,         // e (state), de
  kFieldSmoothingRate = 1u << 6,  // dh
  kFieldStepStart = 1u << 7,      // x_start, v_start, rho_start, h_start (+ e_start with e)
  kFieldEddy = 1u << 8,           // nu_t
  kFieldXsph = 1u << 9,           // xsph
  kFieldSignal = 1u << 10,        // signal
  kFieldsAll = (1u << 11) - 1,
};

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
  // The velocity that carries the momentum the integrator keeps: leap-frog's staggered
  // v^{n+1/2} (v^0 at start); v^{n+1} for the Runge-Kutta steps. m/s
  std::vector<V> v_half;
  std::vector<double> e;  // specific internal energy, J/kg (gas schemes)           (optional)
  // The state at the start of a Runge-Kutta step, Phi^n of W (3.85)-(3.87), (3.92) (optional)
  std::vector<V> x_start, v_start;
  std::vector<double> rho_start, h_start, e_start;

  // --- derived in each step's sweeps ---
  std::vector<double> p;     // pressure (compression positive), Pa
  std::vector<double> c;     // local sound speed sqrt(dp/drho), m/s
  std::vector<V> a;          // acceleration, m/s^2
  std::vector<double> drho;  // density rate, kg/(m^3 s)                              (optional)
  std::vector<double> de;    // internal energy rate, W/kg                           (optional)
  std::vector<double> dh;    // smoothing length rate W (2.22), m/s                  (optional)
  std::vector<M> grad_v;     // velocity gradient BL (22), (grad v)_{kl} = d v_k/d x_l, 1/s (opt.)
  std::vector<M> stress;     // the stress of BL (24)'s pair: sigma' = 2 mu d', BL (23)-(24), or
                             // W (5.11)'s, plus LES's -tau W (5.31)-(5.32), Pa        (optional)
  std::vector<double> nu_t;  // LES's eddy viscosity nu_r, W (5.19), m^2/s              (optional)
  std::vector<V> xsph;       // XSPH's drift correction W (6.6), m/s                    (optional)
  // max_j |h_i u_ij . x_ij| / (|x_ij|^2 + eta^2) of the time step W (3.88), m/s        (optional)
  std::vector<double> signal;

  // --- kernel and gradient corrections (BL section 4) ---
  std::vector<double> shepard;  // sum_b V_b W_b(x_a), the denominator of BL (53)-(54), - (opt.)
  std::vector<V> gamma;         // gamma(x_a) of BL (57), 1/m                              (opt.)
  std::vector<M> L;             // correction matrix L_a of BL (45) or (58), -             (opt.)
  std::vector<double> bl41_deviation;  // |M_a - I|, M_a the matrix of BL (41) before L, - (opt.)

  std::size_t n_real = 0;          // owned particles: indices [0, n_real); ghosts follow
  unsigned optional = kFieldsAll;  // the optional fields in use (the others stay empty)

  std::size_t size() const { return x.size(); }
  bool uses(unsigned field) const { return (optional & field) != 0; }

  // Applies f(name, unit, array) to every state array in use, named as in the checkpoints
  // (run/checkpoint.hpp): re-ordering and checkpoints must never forget one. Add a new field
  // above and here (or in the optional list below), nowhere else.
  template <class F>
  void for_each_named_state_field(F&& f) {
    f("id", "-", id);
    f("x", "m", x);
    f("v", "m/s", v);
    f("m", "kg", m);
    f("rho", "kg/m^3", rho);
    f("h", "m", h);
    f("v_half", "m/s", v_half);
    for_each_named_optional_state_field(optional, f);
  }
  // Applies f to every state array in use.
  template <class F>
  void for_each_state_field(F&& f) {
    for_each_named_state_field([&f](const char*, const char*, auto& field) { f(field); });
  }
  // Applies f to every derived array in use.
  template <class F>
  void for_each_derived_field(F&& f) {
    f(p);
    f(c);
    f(a);
    for_each_optional_derived_field(optional, f);
  }
  // The optional state arrays of the fields in `bits`, with their names and units (e_start
  // needs both of its bits).
  template <class F>
  void for_each_named_optional_state_field(unsigned bits, F&& f) {
    if (bits & kFieldEnergy) f("e", "J/kg", e);
    if (bits & kFieldStepStart) {
      f("x_start", "m", x_start);
      f("v_start", "m/s", v_start);
      f("rho_start", "kg/m^3", rho_start);
      f("h_start", "m", h_start);
      if (bits & kFieldEnergy) f("e_start", "J/kg", e_start);
    }
  }
  template <class F>
  void for_each_optional_state_field(unsigned bits, F&& f) {
    for_each_named_optional_state_field(bits,
                                        [&f](const char*, const char*, auto& field) { f(field); });
  }
  // The optional derived arrays of the fields in `bits`.
  template <class F>
  void for_each_optional_derived_field(unsigned bits, F&& f) {
    if (bits & kFieldDrho) f(drho);
    if (bits & kFieldEnergy) f(de);
    if (bits & kFieldSmoothingRate) f(dh);
    if (bits & kFieldGradV) f(grad_v);
    if (bits & kFieldStress) f(stress);
    if (bits & kFieldEddy) f(nu_t);
    if (bits & kFieldXsph) f(xsph);
    if (bits & kFieldSignal) f(signal);
    if (bits & kFieldShepard) {
      f(shepard);
      f(gamma);
    }
    if (bits & kFieldL) {
      f(L);
      f(bl41_deviation);
    }
  }
  template <class F>
  void for_each_field(F&& f) {
    for_each_state_field(f);
    for_each_derived_field(f);
  }

  // Not inlined: inlined into a caller that adds particles one at a time, GCC 12 loses track of
  // the vectors' sizes and warns of an impossible memmove (-Wstringop-overflow, a false
  // positive), which -Werror makes fatal.
  [[gnu::noinline]] void resize(std::size_t n) {
    for_each_field([n](auto& field) { field.resize(n); });
  }

  // Makes room for n particles without the doubling growth of push-style resizing: room for
  // ghosts grows by a sixteenth more than asked, so that it is not reallocated every step.
  void reserve(std::size_t n) {
    if (x.capacity() >= n) return;
    const std::size_t room = n + n / 16;
    for_each_field([room](auto& field) { field.reserve(room); });
  }

  // Keeps only the optional fields in `fields` allocated (and frees the others). The values of
  // the fields kept stay (a gas's internal energy, set with the particles); derived fields are
  // recomputed before they are read.
  void use_only(unsigned fields) {
    const std::size_t n = size();
    const auto release = [](auto& field) {
      field.clear();
      field.shrink_to_fit();
    };
    // The arrays of the fields dropped (e_start goes with either of its two bits).
    for_each_optional_state_field(kFieldsAll & ~fields, release);
    if ((fields & kFieldEnergy) == 0 || (fields & kFieldStepStart) == 0) release(e_start);
    for_each_optional_derived_field(kFieldsAll & ~fields, release);
    optional = fields;
    resize(n);
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
};

}  // namespace flume
