// An axis-aligned box whose sides are mirror walls (ghost particles, W 6.1 (6.1)-(6.2)) or open.
// Free slip reverses the normal velocity of the ghost, no slip both components (W 6.1). A
// particle near a corner also gets the double (or triple) reflection, which W does not describe
// but which completes the kernel support there; its velocity map is the composition of the two
// walls' maps.
#pragma once

#include <array>
#include <string>

#include "flume/boundaries/halo.hpp"

namespace flume {

enum class WallKind { free_slip, no_slip, open };

template <int D>
struct BoxWalls {
  Vec<D> lo, hi;                                  // box corners, m
  std::array<std::array<WallKind, 2>, D> kind{};  // [axis][0 = lower side, 1 = upper side]

  // Rebuilds the halo: one ghost per (particle, non-empty set of nearby walls with at most one
  // wall per axis). range is the kernel support radius. Deterministic order: by particle, then
  // by wall combination.
  void build_halo(const ParticleSet<D>& ps, double range, Halo<D>& halo) const {
    halo.clear();
    for (std::size_t i = 0; i < ps.n_real; ++i) {
      // choice[k]: 0 none, 1 lower wall, 2 upper wall
      std::array<int, D> near{};
      for (int k = 0; k < D; ++k) {
        near[k] = 0;
        if (kind[k][0] != WallKind::open && ps.x[i][k] - lo[k] < range) near[k] |= 1;
        if (kind[k][1] != WallKind::open && hi[k] - ps.x[i][k] < range) near[k] |= 2;
      }
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
        g.source = static_cast<std::uint32_t>(i);
        for (int a = 0; a < D; ++a) {
          g.scale[a] = 1.0;
          g.vscale[a] = 1.0;
        }
        for (int a = 0; a < D; ++a) {
          if (choice[a] == 0) continue;
          const double wall = choice[a] == 1 ? lo[a] : hi[a];
          g.scale[a] = -1.0;
          g.shift[a] = 2.0 * wall;
          if (kind[a][choice[a] - 1] == WallKind::no_slip) {
            for (int b = 0; b < D; ++b)
              g.vscale[b] = -g.vscale[b];
          } else {
            g.vscale[a] = -g.vscale[a];
          }
        }
        halo.add(g);
      }
    }
  }

  // A particle that has stepped across a mirror wall is replaced by its mirror image (W (6.8),
  // "put back"): across a symmetry plane the particle and its ghost are interchangeable, so the
  // image is the state the mirror condition implies. Its velocities are mapped as the ghost's are.
  // Particles further out than `range` are left alone for first_outside() to report.
  void reflect_crossings(ParticleSet<D>& ps, double range) const {
    for (std::size_t i = 0; i < ps.n_real; ++i) {
      for (int k = 0; k < D; ++k) {
        for (int side = 0; side < 2; ++side) {
          const WallKind w = kind[k][side];
          if (w == WallKind::open) continue;
          const double wall = side == 0 ? lo[k] : hi[k];
          const double depth = side == 0 ? wall - ps.x[i][k] : ps.x[i][k] - wall;
          if (!(depth > 0.0) || depth > range) continue;
          ps.x[i][k] = 2.0 * wall - ps.x[i][k];
          if (w == WallKind::no_slip) {
            ps.v[i] = -ps.v[i];
            ps.v_half[i] = -ps.v_half[i];
          } else {
            ps.v[i][k] = -ps.v[i][k];
            ps.v_half[i][k] = -ps.v_half[i][k];
          }
        }
      }
    }
  }

  // Index of the first real particle outside the box, or -1. Walls are impermeable and open
  // sides let particles leave the domain: either way such a particle is lost to the run.
  long first_outside(const ParticleSet<D>& ps) const {
    for (std::size_t i = 0; i < ps.n_real; ++i)
      for (int k = 0; k < D; ++k)
        if (!(ps.x[i][k] >= lo[k] && ps.x[i][k] <= hi[k])) return static_cast<long>(i);
    return -1;
  }
};

}  // namespace flume
