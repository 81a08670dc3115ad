// An axis-aligned box whose sides are mirror walls (ghost particles, W 6.1 (6.1)-(6.2)) or open.
// Free slip reverses the normal velocity of the ghost, no slip both components (W 6.1). A
// particle near a corner also gets the double (or triple) reflection, which W does not describe
// but which completes the kernel support there; its velocity map is the composition of the two
// walls' maps.
// A wall may move along its normal with a prescribed motion (wall_motion.hpp): the bore's push
// wall (BL 5.4), a piston wave-maker. Its ghosts are mirrored about where it stands now, and
// mirror its velocity relative to the wall: v' = P v + (I - P) u_w, i.e. the normal component
// -v_n + 2 u_w (the wall's velocity is normal to it, so free slip leaves the tangential
// component alone and no slip reverses it about zero). A fluid moving with the wall then sees
// ghosts moving with it too. set_time() places the walls; every other member uses those places.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "flume/boundaries/halo.hpp"
#include "flume/boundaries/wall_motion.hpp"

namespace flume {

enum class WallKind { free_slip, no_slip, open };

template <int D>
struct BoxWalls {
  Vec<D> lo, hi;                                      // box corners at t = 0, m
  std::array<std::array<WallKind, 2>, D> kind{};      // [axis][0 = lower side, 1 = upper side]
  std::array<std::array<WallMotion, 2>, D> motion{};  // [axis][side]; none by default

  // Places the moving walls where they stand at time t (s).
  void set_time(double t) {
    for (int k = 0; k < D; ++k)
      for (int side = 0; side < 2; ++side) {
        const double rest = side == 0 ? lo[k] : hi[k];
        place_[k][side] = rest + motion[k][side].displacement(t);
        speed_[k][side] = motion[k][side].speed(t);
      }
    placed_ = true;
  }
  // Where the wall on `side` of axis k stands now, m, and its velocity along k, m/s.
  double wall(int k, int side) const {
    return placed_ ? place_[k][side] : (side == 0 ? lo[k] : hi[k]);
  }
  double wall_speed(int k, int side) const { return placed_ ? speed_[k][side] : 0.0; }

  // Rebuilds the halo: one ghost per (particle, non-empty set of nearby walls with at most one
  // wall per axis). range is the kernel support radius. Deterministic order: by particle, then
  // by wall combination (a count per particle, a prefix sum, then a parallel fill).
  void build_halo(const ParticleSet<D>& ps, double range, Halo<D>& halo) const {
    const auto n = static_cast<long>(ps.n_real);
    std::vector<std::uint32_t>& first = first_ghost_;
    first.resize(ps.n_real + 1);
#pragma omp parallel for schedule(static)
    for (long ii = 0; ii < n; ++ii) {
      const auto i = static_cast<std::size_t>(ii);
      first[i + 1] = static_cast<std::uint32_t>(for_each_image(ps.x[i], range, [](auto&&) {}));
    }
    first[0] = 0;
    for (std::size_t i = 0; i < ps.n_real; ++i)
      first[i + 1] += first[i];
    auto& maps = halo.resize(first[ps.n_real]);
#pragma omp parallel for schedule(static)
    for (long ii = 0; ii < n; ++ii) {
      const auto i = static_cast<std::size_t>(ii);
      std::size_t k = first[i];
      for_each_image(ps.x[i], range, [&](GhostMap<D> g) {
        g.source = static_cast<std::uint32_t>(i);
        maps[k++] = g;
      });
    }
  }

  // Calls f(map) for each mirror image of a particle at x (source not set); returns how many.
  template <class F>
  int for_each_image(const Vec<D>& x, double range, F&& f) const {
    // choice[k]: 0 none, 1 lower wall, 2 upper wall
    std::array<int, D> near{};
    bool any = false;
    for (int k = 0; k < D; ++k) {
      near[k] = 0;
      if (kind[k][0] != WallKind::open && x[k] - wall(k, 0) < range) near[k] |= 1;
      if (kind[k][1] != WallKind::open && wall(k, 1) - x[k] < range) near[k] |= 2;
      any = any || near[k] != 0;
    }
    if (!any) return 0;
    int count = 0;
    std::array<int, D> choice{};
    while (true) {
      int k = 0;
      // next combination in lexicographic order over choice[k] in {0, 1, 2}
      while (k < D) {
        if (++choice[k] <= 2) break;
        choice[k++] = 0;
      }
      if (k == D) break;
      bool valid = true;
      for (int a = 0; a < D; ++a)
        if (choice[a] != 0 && !(near[a] & choice[a])) valid = false;
      if (!valid) continue;
      GhostMap<D> g;
      for (int a = 0; a < D; ++a) {
        g.scale[a] = 1.0;
        g.vscale[a] = 1.0;
      }
      // The walls' maps composed in axis order: v -> P_a (P v + c) + c_a, c_a = 2 u_a e_a.
      for (int a = 0; a < D; ++a) {
        if (choice[a] == 0) continue;
        const int side = choice[a] - 1;
        g.scale[a] = -1.0;
        g.shift[a] = 2.0 * wall(a, side);
        if (kind[a][side] == WallKind::no_slip) {
          for (int b = 0; b < D; ++b) {
            g.vscale[b] = -g.vscale[b];
            g.vshift[b] = -g.vshift[b];
          }
        } else {
          g.vscale[a] = -g.vscale[a];
          g.vshift[a] = -g.vshift[a];
        }
        g.vshift[a] += 2.0 * wall_speed(a, side);
      }
      f(g);
      ++count;
    }
    return count;
  }

  // A particle that has stepped across a mirror wall is replaced by its mirror image (W (6.8),
  // "put back"): across a symmetry plane the particle and its ghost are interchangeable, so the
  // image is the state the mirror condition implies. Its velocities are mapped as the ghost's are.
  // Particles further out than `range` are left alone for first_outside() to report.
  void reflect_crossings(ParticleSet<D>& ps, double range) const {
    const auto n = static_cast<long>(ps.n_real);
#pragma omp parallel for schedule(static)
    for (long ii = 0; ii < n; ++ii) {
      const auto i = static_cast<std::size_t>(ii);
      for (int k = 0; k < D; ++k) {
        for (int side = 0; side < 2; ++side) {
          const WallKind w = kind[k][side];
          if (w == WallKind::open) continue;
          const double at = wall(k, side);
          const double depth = side == 0 ? at - ps.x[i][k] : ps.x[i][k] - at;
          if (!(depth > 0.0) || depth > range) continue;
          ps.x[i][k] = 2.0 * at - ps.x[i][k];
          if (w == WallKind::no_slip) {
            ps.v[i] = -ps.v[i];
            ps.v_half[i] = -ps.v_half[i];
          } else {
            ps.v[i][k] = -ps.v[i][k];
            ps.v_half[i][k] = -ps.v_half[i][k];
          }
          const double u2 = 2.0 * wall_speed(k, side);
          ps.v[i][k] += u2;
          ps.v_half[i][k] += u2;
        }
      }
    }
  }

  // Index of the first real particle outside the box, or -1. Walls are impermeable and open
  // sides let particles leave the domain: either way such a particle is lost to the run.
  long first_outside(const ParticleSet<D>& ps) const {
    const auto n = static_cast<long>(ps.n_real);
    long first = n;
#pragma omp parallel for schedule(static) reduction(min : first)
    for (long i = 0; i < n; ++i)
      for (int k = 0; k < D; ++k)
        if (!(ps.x[static_cast<std::size_t>(i)][k] >= wall(k, 0) &&
              ps.x[static_cast<std::size_t>(i)][k] <= wall(k, 1)))
          first = std::min(first, i);
    return first < n ? first : -1;
  }

  // Scratch of build_halo: per particle, the index of its first ghost (reused between steps).
  mutable std::vector<std::uint32_t> first_ghost_;

 private:
  std::array<std::array<double, 2>, D> place_{}, speed_{};
  bool placed_ = false;  // before set_time() the walls stand at lo, hi
};

}  // namespace flume
