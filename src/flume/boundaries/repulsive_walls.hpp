// Walls of repulsive boundary particles (W 6.2): plane slopes at any angle and the piston-flap
// paddle W (6.9), for 2D tanks. A wall is a straight segment from `from` to `to` in the (x, y)
// plane, the fluid on its left as one walks from `from` to `to` (its normal n is the tangent
// turned a quarter turn anticlockwise); boundary particles stand on it every `spacing`, the
// first at `from`. Each pushes the fluid particles near it with the Lennard-Jones force W (6.7)
// or the Monaghan-Kos force W (6.10)-(6.12), an acceleration added to the scheme's (free slip:
// the boundary particles take no part in the SPH sums, errata.md). A fluid particle that has
// crossed a wall (it stands behind it, within the wall's length) is put back W (6.8) at
// put_back_distance in front of it, its velocity relative to the wall mirrored in the normal
// direction as a mirror wall's put-back does (box_walls.hpp; W does not say, errata.md).
// Why boundary particles for slopes rather than mirror ghosts about an inclined plane: a slope
// meets the bed and the side walls at corners that are not right angles, where mirror images of
// mirror images overlap the fluid or leave gaps, and a paddle is a plane that turns; boundary
// particles need no rule at corners and are what W (6.7)-(6.12) and Dalrymple & Rogers use.
// Their price: kernel sums near the wall are one-sided (a summation density reads low there,
// so the wave-tank cases evolve the density, as W does).
// Everything here is per particle, over the walls in a fixed order: bit-identical results for
// any thread count.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "flume/boundaries/piston_flap_w69.hpp"
#include "flume/core/particle_set.hpp"
#include "flume/equations/repulsion_lennard_jones_w67.hpp"
#include "flume/equations/repulsion_monaghan_kos_w610.hpp"
#include "flume/schemes/particle_passes.hpp"

namespace flume {

enum class Repulsion { monaghan_kos, lennard_jones };

template <int D>
struct RepulsiveWall {
  Vec<D> from, to;  // the wall at rest, m (only x and y are used: 2D)
  Repulsion force = Repulsion::monaghan_kos;
  double spacing = 0.0;            // the boundary particles' spacing, m
  LennardJonesW67 lennard_jones;   // W (6.7)'s constants
  double sound_speed = 0.0;        // c of Monaghan-Kos's A = 0.01 c^2 / h, m/s
  double reach = 0.0;              // m: Monaghan-Kos's q = y / reach; 0 = 2h
  double put_back_distance = 0.0;  // Delta z of W (6.8), m
  double clearance = 0.0;          // m: no fluid particle starts nearer (the force's reach)
  PistonFlapW69 paddle;            // the wall's motion, W (6.9) (none unless its stroke is set)
};

template <int D>
class RepulsiveWalls {
 public:
  RepulsiveWalls() = default;
  explicit RepulsiveWalls(std::vector<RepulsiveWall<D>> walls) : walls_(std::move(walls)) {
    placed_.resize(walls_.size());
    set_time(0.0);
  }

  bool empty() const { return walls_.empty(); }
  std::size_t size() const { return walls_.size(); }

  // Places the walls where they stand at time t, s (a paddle moves, W (6.9)).
  void set_time(double t) {
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      const RepulsiveWall<D>& wall = walls_[w];
      Placed& p = placed_[w];
      // W (6.9)'s y is the height above the paddle's foot, its lower end.
      const double foot = std::min(wall.from[1], wall.to[1]);
      p.from = wall.from;
      p.to = wall.to;
      p.from[0] += wall.paddle.displacement(wall.from[1] - foot, t);
      p.to[0] += wall.paddle.displacement(wall.to[1] - foot, t);
      p.speed_from = wall.paddle.speed(wall.from[1] - foot, t);
      p.speed_to = wall.paddle.speed(wall.to[1] - foot, t);
      const Vec<D> along = p.to - p.from;
      p.length = norm(along);
      p.tangent = along * (1.0 / p.length);
      p.normal = Vec<D>{};
      p.normal[0] = -p.tangent[1];
      p.normal[1] = p.tangent[0];
      p.last = static_cast<long>(std::floor(p.length / wall.spacing * (1.0 + 1e-12)));
    }
  }

  // Where wall w stands now: its ends, unit tangent and normal (into the fluid).
  const Vec<D>& from(std::size_t w) const { return placed_[w].from; }
  const Vec<D>& to(std::size_t w) const { return placed_[w].to; }
  const Vec<D>& normal(std::size_t w) const { return placed_[w].normal; }
  // The boundary particles of wall w: k = 0 .. last at from + k spacing tangent.
  long last_particle(std::size_t w) const { return placed_[w].last; }
  Vec<D> particle(std::size_t w, long k) const {
    return placed_[w].from + placed_[w].tangent * (static_cast<double>(k) * walls_[w].spacing);
  }

  // The walls' acceleration of a fluid particle at x with smoothing length h, m/s^2.
  Vec<D> acceleration(const Vec<D>& x, double h) const {
    Vec<D> a{};
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      const RepulsiveWall<D>& wall = walls_[w];
      const Placed& p = placed_[w];
      const auto [s, y] = p.local(x);
      const double ds = wall.spacing;
      if (wall.force == Repulsion::monaghan_kos) {
        const MonaghanKosW610 mk{wall.sound_speed, ds, wall.put_back_distance, wall.reach};
        if (!(y < (wall.reach > 0.0 ? wall.reach : 2.0 * h))) continue;  // q > 1 (or a NaN)
        // The boundary particles within one spacing along the wall, W (6.10) summed.
        const long k0 = index_at(std::ceil(s / ds - 1.0), p.last);
        const long k1 = index_at(std::floor(s / ds + 1.0), p.last);
        double share = 0.0;
        for (long k = std::max(k0, 0L); k <= std::min(k1, p.last); ++k)
          share += mk.tangential_part(s - static_cast<double>(k) * ds);
        a += p.normal * (mk.normal_part(y, h) * share);
      } else {
        const double r0 = wall.lennard_jones.cutoff;
        if (!(std::abs(y) <= r0)) continue;
        const long k0 = index_at(std::ceil((s - r0) / ds), p.last);
        const long k1 = index_at(std::floor((s + r0) / ds), p.last);
        for (long k = std::max(k0, 0L); k <= std::min(k1, p.last); ++k)
          a += wall.lennard_jones(x - particle(w, k));
      }
    }
    return a;
  }

  // Adds the walls' accelerations to every real particle's ps.a.
  void add_accelerations(ParticleSet<D>& ps) const {
    if (walls_.empty()) return;
    for_each_real(ps.n_real, [&](std::size_t i) { ps.a[i] += acceleration(ps.x[i], ps.h[i]); });
  }

  // W (6.8) for the real particles [b, e): a particle behind a wall, within its length, is put
  // back at put_back_distance in front of it, with the normal part of its velocity relative to
  // the wall mirrored (v_n -> 2 u_n - v_n, u the wall's velocity there: a paddle's W (6.9)).
  void put_back(ParticleSet<D>& ps, std::size_t b, std::size_t e) const {
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      const Placed& p = placed_[w];
      const double dz = walls_[w].put_back_distance;
      for (std::size_t i = b; i < e; ++i) {
        const auto [s, y] = p.local(ps.x[i]);
        if (!(y < 0.0 && s >= 0.0 && s <= p.length)) continue;
        ps.x[i] += p.normal * (dz - y);
        // The paddle's velocity is along x and linear in the height: linear along the wall.
        const double f = s / p.length;
        Vec<D> u{};
        u[0] = (1.0 - f) * p.speed_from + f * p.speed_to;
        const double un = dot(u, p.normal);
        ps.v[i] += p.normal * (2.0 * (un - dot(ps.v[i], p.normal)));
        ps.v_half[i] += p.normal * (2.0 * (un - dot(ps.v_half[i], p.normal)));
      }
    }
  }

  // Whether x stands behind a wall (within its length) or nearer to it than its clearance:
  // where a fluid block places no particle. The clearance is the force's reach unless the case
  // sets it (Monaghan-Kos's, 2h by default; r0 for Lennard-Jones): water at rest settles just
  // inside it, where the wall's push balances the pressure's one-sided pull (with c0 = 83 m/s, at q
  // of about 0.9 under a 0.15 m column, estimating the pull as 2 p / (rho h)). Water placed nearer
  // starts with a push of thousands of m/s^2 (R at half a spacing) and is thrown off the wall.
  bool blocked(const Vec<D>& x) const {
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      const Placed& p = placed_[w];
      const auto [s, y] = p.local(x);
      if (y < walls_[w].clearance && s >= 0.0 && s <= p.length) return true;
    }
    return false;
  }

 private:
  // A boundary particle's index k, clamped to [-1, last + 1] before it is made an integer (a
  // particle far along the wall's line would overflow a long); -1 and last + 1 are outside the
  // wall, so an empty range stays empty.
  static long index_at(double k, long last) {
    return static_cast<long>(std::clamp(k, -1.0, static_cast<double>(last + 1)));
  }

  struct Placed {
    Vec<D> from, to, tangent, normal;
    double length = 0.0;
    double speed_from = 0.0, speed_to = 0.0;  // the wall's velocity along x at its ends, m/s
    long last = 0;                            // index of the last boundary particle

    // x's place relative to the wall: {s, y}, m, along it from its first particle and in
    // front of it (along the normal).
    std::array<double, 2> local(const Vec<D>& x) const {
      const Vec<D> rel = x - from;
      return {dot(rel, tangent), dot(rel, normal)};
    }
  };
  std::vector<RepulsiveWall<D>> walls_;
  std::vector<Placed> placed_;
};

}  // namespace flume
