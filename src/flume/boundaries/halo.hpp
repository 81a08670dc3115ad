// One mechanism for every ghost copy of a particle: mirror walls now, periodic images and MPI
// halos later (Cabana's halo, LAMMPS's ghost atoms). A ghost is an affine image of a real
// "source" particle, x' = S x + t with S diagonal (+-1), and its velocity is v' = P v + c with P
// diagonal (+-1) and c the moving walls' part ((I - P) u_w, box_walls.hpp; zero for static ones).
// Equations never know whether a neighbour is a ghost: the halo appends the ghosts after the real
// particles and refreshes their fields from the sources between sweeps.
#pragma once

#include <cstdint>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/equations/eos_tait.hpp"

namespace flume {

template <int D>
struct GhostMap {
  std::uint32_t source = 0;  // index of the real particle copied
  Vec<D> scale;              // S: +1 (shift) or -1 (reflection) per axis
  Vec<D> shift;              // t, m
  Vec<D> vscale;             // P: +1 or -1 per axis
  Vec<D> vshift;             // c, m/s
};

template <int D>
class Halo {
 public:
  void clear() { maps_.clear(); }
  void add(const GhostMap<D>& g) { maps_.push_back(g); }
  // n maps to be filled in place (by the boundary that builds the halo).
  std::vector<GhostMap<D>>& resize(std::size_t n) {
    maps_.resize(n);
    return maps_;
  }
  std::size_t size() const { return maps_.size(); }

  // Hydrostatic mirror ghosts (boundaries.ghost_pressure = "hydrostatic"): a reflected ghost
  // (any S entry -1) carries its source's pressure plus the hydrostatic step between them,
  //   p_g = p(rho_s) + rho_s g . (x_g - x_s),
  // and the Tait density of that pressure (BL (60) inverted). W 6.1 mirrors p and rho as they
  // are, so below a floor the ghosts stand at the pressure of the water above it: the pressure
  // profile folds into a V at the wall. The bottom row then feels less push from below than a
  // continued column would give, and W (6.3)'s filter, which averages across the wall, lowers
  // its density at every filtering (the creep that brings a still tank's bottom row down onto
  // its own ghosts, issue 10). With the step the profile runs on straight through the wall, as
  // Adami, Hu & Adams (2012) extrapolate a wall's pressure. Side walls (g . (x_g - x_s) = 0)
  // and periodic images (shifts only) are unchanged.
  void set_hydrostatic(const Vec<D>& gravity, const TaitEos& eos) {
    hydrostatic_ = true;
    gravity_ = gravity;
    eos_ = eos;
  }
  bool hydrostatic() const { return hydrostatic_; }
  const std::vector<GhostMap<D>>& maps() const { return maps_; }

  // Where ghost g stands: S x_source + t.
  Vec<D> position(const ParticleSet<D>& ps, std::size_t g) const {
    return mul(maps_[g].scale, ps.x[maps_[g].source]) + maps_[g].shift;
  }

  // Re-orders the ghosts: new ghost k is old ghost order[k] (the cell grid sorts them by cell).
  void reorder(const std::vector<std::uint32_t>& order) {
    scratch_.resize(maps_.size());
    for (std::size_t k = 0; k < order.size(); ++k)
      scratch_[k] = maps_[order[k]];
    maps_.swap(scratch_);
  }

  // Appends one ghost per map after the real particles and fills its state.
  void append_ghosts(ParticleSet<D>& ps) const {
    const std::size_t n = ps.n_real;
    ps.reserve(n + maps_.size());
    ps.resize(n + maps_.size());
    const auto count = static_cast<long>(maps_.size());
    const bool energy = ps.uses(kFieldEnergy);
#pragma omp parallel for schedule(static)
    for (long gg = 0; gg < count; ++gg) {
      const auto g = static_cast<std::size_t>(gg);
      const auto& mp = maps_[g];
      const std::size_t i = n + g;
      const std::size_t s = mp.source;
      ps.id[i] = ps.id[s];
      ps.x[i] = mul(mp.scale, ps.x[s]) + mp.shift;
      ps.v[i] = mul(mp.vscale, ps.v[s]) + mp.vshift;
      ps.v_half[i] = mul(mp.vscale, ps.v_half[s]) + mp.vshift;
      ps.m[i] = ps.m[s];
      ps.rho[i] = ps.rho[s];
      ps.h[i] = ps.h[s];
      ps.p[i] = ps.p[s];
      ps.c[i] = ps.c[s];
      if (energy) ps.e[i] = ps.e[s];  // W 6.1: ghosts copy the internal energy too
      if (hydrostatic_) hydrostatic_state(ps, g);
    }
  }

  // The ghosts' density after their sources' has changed (a filter, a summation): copied, or
  // with hydrostatic ghosts their density, pressure and sound speed from the source's density.
  void update_density(ParticleSet<D>& ps) const {
    if (!hydrostatic_) return update_scalar(ps, ps.rho);
    for (std::size_t g = 0; g < maps_.size(); ++g)
      hydrostatic_state(ps, g);
  }

  // The ghosts' pressure and sound speed after their sources' have been computed: copied, or
  // with hydrostatic ghosts (whose density then moves with them) as update_density.
  void update_pressure(ParticleSet<D>& ps) const {
    if (!hydrostatic_) {
      update_scalar(ps, ps.p);
      update_scalar(ps, ps.c);
      return;
    }
    for (std::size_t g = 0; g < maps_.size(); ++g)
      hydrostatic_state(ps, g);
  }

  // Maps a velocity field (v or v_half) from the sources to their ghosts. A moving wall's c is
  // that of the time the halo was built (t^n) for v_half too: exact for the bore's push wall
  // (constant speed); for an oscillating wall an O(dt) lag in the ghosts' half-step velocity.
  void update_velocity(const ParticleSet<D>& ps, std::vector<Vec<D>>& f) const {
    for (std::size_t g = 0; g < maps_.size(); ++g)
      f[ps.n_real + g] = mul(maps_[g].vscale, f[maps_[g].source]) + maps_[g].vshift;
  }

  // The Shepard sum and gamma of BL (57) of a ghost: its neighbourhood is the mirror (or
  // shifted) image of its source's, so S is the same and gamma maps like a position difference
  // (S gamma).
  void update_shepard(ParticleSet<D>& ps) const {
    for (std::size_t g = 0; g < maps_.size(); ++g) {
      const auto& mp = maps_[g];
      const std::size_t i = ps.n_real + g;
      ps.shepard[i] = ps.shepard[mp.source];
      ps.gamma[i] = mul(mp.scale, ps.gamma[mp.source]);
    }
  }

  // The CSPH correction matrix of a ghost maps like S L S (same reason).
  void update_corrections(ParticleSet<D>& ps) const {
    for (std::size_t g = 0; g < maps_.size(); ++g) {
      const auto& mp = maps_[g];
      const std::size_t i = ps.n_real + g;
      for (int k = 0; k < D; ++k)
        for (int l = 0; l < D; ++l)
          ps.L[i](k, l) = mp.scale[k] * ps.L[mp.source](k, l) * mp.scale[l];
    }
  }

  // Copies a scalar field (density, pressure, ...) from the sources to their ghosts.
  void update_scalar(const ParticleSet<D>& ps, std::vector<double>& f) const {
    for (std::size_t g = 0; g < maps_.size(); ++g)
      f[ps.n_real + g] = f[maps_[g].source];
  }

  // The ghost's velocity field is v'(x) = P v(S^-1 (x - t)), so its gradient is P G S
  // (S = S^-1 for +-1 entries). For a free-slip mirror (P = S) this flips the shear
  // components, so the wall carries no shear stress; for no-slip (P = -I) the wall-normal
  // derivative of the tangential velocity keeps its sign (du/dy is continuous: wall shear).
  void update_velocity_gradient(ParticleSet<D>& ps) const {
    for (std::size_t g = 0; g < maps_.size(); ++g) {
      const auto& mp = maps_[g];
      const auto& G = ps.grad_v[mp.source];
      Mat<D> out;
      for (int k = 0; k < D; ++k)
        for (int l = 0; l < D; ++l)
          out(k, l) = mp.vscale[k] * G(k, l) * mp.scale[l];
      ps.grad_v[ps.n_real + g] = out;
    }
  }

 private:
  // rho, p, c of ghost g from its source's density, with the hydrostatic step when it is a
  // reflection (set_hydrostatic); a shifted (periodic) image copies them.
  void hydrostatic_state(ParticleSet<D>& ps, std::size_t g) const {
    const auto& mp = maps_[g];
    const std::size_t i = ps.n_real + g, s = mp.source;
    bool reflected = false;
    for (int k = 0; k < D; ++k)
      reflected = reflected || mp.scale[k] < 0.0;
    if (!reflected) {
      ps.rho[i] = ps.rho[s];
      ps.p[i] = ps.p[s];
      ps.c[i] = ps.c[s];
      return;
    }
    const double rise = dot(gravity_, ps.x[i] - ps.x[s]);  // g . (x_g - x_s), m^2/s^2
    const double p = eos_.pressure(ps.rho[s]) + ps.rho[s] * rise;
    ps.rho[i] = eos_.density_at(p);
    ps.p[i] = p;
    ps.c[i] = eos_.sound_speed(ps.rho[i], p);
  }

  static Vec<D> mul(const Vec<D>& s, const Vec<D>& v) {
    Vec<D> r;
    for (int k = 0; k < D; ++k)
      r[k] = s[k] * v[k];
    return r;
  }
  std::vector<GhostMap<D>> maps_;
  std::vector<GhostMap<D>> scratch_;  // reused by reorder
  bool hydrostatic_ = false;
  Vec<D> gravity_{};
  TaitEos eos_{};
};

}  // namespace flume
