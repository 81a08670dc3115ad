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
// A periodic axis (W 6.1) joins its two ends: the ghosts of the particles near one end are
// their copies shifted by the box's length to beyond the other end, velocities unchanged, and a
// particle that steps out of one end re-enters at the other (re-injection). W 6.4.2 forms its
// wave in a closed tank and joins the ends once it has formed: before periodic_from the two
// sides are free-slip mirror walls.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "flume/boundaries/halo.hpp"
#include "flume/boundaries/wall_motion.hpp"
#include "flume/neighbors/cell_grid.hpp"

namespace flume {

enum class WallKind { free_slip, no_slip, open, periodic };

template <int D>
struct BoxWalls {
  Vec<D> lo, hi;                                      // box corners at t = 0, m
  std::array<std::array<WallKind, 2>, D> kind{};      // [axis][0 = lower side, 1 = upper side]
  std::array<std::array<WallMotion, 2>, D> motion{};  // [axis][side]; none by default
  double periodic_from = 0.0;  // s: before it, periodic sides act as free-slip walls

  // Places the moving walls where they stand at time t (s).
  void set_time(double t) {
    for (int k = 0; k < D; ++k)
      for (int side = 0; side < 2; ++side) {
        const double rest = side == 0 ? lo[k] : hi[k];
        place_[k][side] = rest + motion[k][side].displacement(t);
        speed_[k][side] = motion[k][side].speed(t);
      }
    periodic_on_ = t >= periodic_from;
    placed_ = true;
  }
  // What the side of axis k acts as now: its kind, except a periodic side before
  // periodic_from, which is a free-slip wall.
  WallKind acts_as(int k, int side) const {
    const WallKind w = kind[k][side];
    return w == WallKind::periodic && !periodic_now() ? WallKind::free_slip : w;
  }
  bool periodic_now() const { return placed_ ? periodic_on_ : periodic_from <= 0.0; }
  // Where the wall on `side` of axis k stands now, m, and its velocity along k, m/s.
  double wall(int k, int side) const {
    return placed_ ? place_[k][side] : (side == 0 ? lo[k] : hi[k]);
  }
  double wall_speed(int k, int side) const { return placed_ ? speed_[k][side] : 0.0; }

  // The points farther than range from every wall: the box (inner_lo, inner_hi), infinite on
  // open sides. Only particles outside it have mirror images.
  void clear_of_walls(double range, Vec<D>& inner_lo, Vec<D>& inner_hi) const {
    const double inf = std::numeric_limits<double>::infinity();
    for (int k = 0; k < D; ++k) {
      inner_lo[k] = acts_as(k, 0) == WallKind::open ? -inf : wall(k, 0) + range;
      inner_hi[k] = acts_as(k, 1) == WallKind::open ? inf : wall(k, 1) - range;
    }
  }

  // Rebuilds the halo: one ghost per (particle, non-empty set of nearby walls with at most one
  // wall per axis). range is the kernel support radius. ps is sorted into grid (a simulation
  // step's order): only the particles of the cells near the walls are looked at
  // (CellGrid::runs_outside of clear_of_walls), since no other particle has an image.
  // Deterministic order: by particle, then by wall combination.
  void build_halo(const ParticleSet<D>& ps, double range, Halo<D>& halo,
                  const CellGrid<D>& grid) const {
    Vec<D> inner_lo, inner_hi;
    clear_of_walls(range, inner_lo, inner_hi);
    runs_.clear();
    grid.runs_outside(inner_lo, inner_hi, runs_);
    build_halo_of(ps, range, halo, runs_);
  }
  // The same, looking at every real particle (in any order).
  void build_halo(const ParticleSet<D>& ps, double range, Halo<D>& halo) const {
    const std::pair<std::uint32_t, std::uint32_t> all{0, static_cast<std::uint32_t>(ps.n_real)};
    build_halo_of(ps, range, halo, std::span(&all, 1));
  }

  // Calls f(map) for each mirror image of a particle at x (source not set); returns how many.
  template <class F>
  int for_each_image(const Vec<D>& x, double range, F&& f) const {
    // choice[k]: 0 none, 1 lower wall, 2 upper wall
    std::array<int, D> near{};
    bool any = false;
    for (int k = 0; k < D; ++k) {
      near[k] = 0;
      if (acts_as(k, 0) != WallKind::open && x[k] - wall(k, 0) < range) near[k] |= 1;
      if (acts_as(k, 1) != WallKind::open && wall(k, 1) - x[k] < range) near[k] |= 2;
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
        if (acts_as(a, side) == WallKind::periodic) {
          // The copy beyond the other end: shifted by the box's length, velocity as it is.
          g.shift[a] = (side == 0 ? 1.0 : -1.0) * (hi[a] - lo[a]);
          continue;
        }
        g.scale[a] = -1.0;
        g.shift[a] = 2.0 * wall(a, side);
        if (acts_as(a, side) == WallKind::no_slip) {
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
  // Particles further out than `range` are left alone for inside() to report. For the real
  // particles [b, e); the walls are taken in turn (axis, then side), each over every particle,
  // with selects rather than branches on the particle, so that the loops vectorise.
  void put_back(ParticleSet<D>& ps, std::size_t b, std::size_t e, double range) const {
    Vec<D> least, most;
    for (int k = 0; k < D; ++k) {
      least[k] = -std::numeric_limits<double>::infinity();
      most[k] = std::numeric_limits<double>::infinity();
    }
    put_back(ps, b, e, range, least, most);
  }
  // The same, knowing that the positions of [b, e) lie within [least, most] on each axis (NaN
  // ones aside): a wall that none of them stands beyond is skipped without a scan (most blocks,
  // most steps). Returns whether a wall's put-back ran over the block (its particles may have
  // moved; otherwise none has).
  bool put_back(ParticleSet<D>& ps, std::size_t b, std::size_t e, double range, const Vec<D>& least,
                const Vec<D>& most) const {
    return [&]<int... K>(std::integer_sequence<int, K...>) {
      return (put_back_axis<K>(ps, b, e, range, least[K], most[K]) | ...);
    }
    (std::make_integer_sequence<int, D>{});
  }
  // put_back for every real particle (a simulation does it block by block in the drift's pass).
  void reflect_crossings(ParticleSet<D>& ps, double range) const {
    put_back(ps, 0, ps.n_real, range);
  }

  // Whether particle i is inside the box (a NaN position is not). Walls are impermeable and
  // open sides let particles leave the domain: either way a particle outside is lost to the run.
  [[gnu::always_inline]] bool inside(const ParticleSet<D>& ps, std::size_t i) const {
    Vec<D> at_lo, at_hi;
    places(at_lo, at_hi);
    return inside(ps.x[i], at_lo, at_hi);
  }
  // The walls' places now, lower and upper on each axis: taken once before a loop over the
  // particles that tests inside(x, lo, hi) (read in the loop through wall(), with its test on
  // a moving wall, they kept the simulation's checks scalar).
  void places(Vec<D>& at_lo, Vec<D>& at_hi) const {
    for (int k = 0; k < D; ++k) {
      at_lo[k] = wall(k, 0);
      at_hi[k] = wall(k, 1);
    }
  }
  [[gnu::always_inline]] static bool inside(const Vec<D>& x, const Vec<D>& at_lo,
                                            const Vec<D>& at_hi) {
    bool in = true;
    for (int k = 0; k < D; ++k)
      in = in & (x[k] >= at_lo[k]) & (x[k] <= at_hi[k]);
    return in;
  }
  // Index of the first real particle outside the box, or -1.
  long first_outside(const ParticleSet<D>& ps) const {
    const auto n = static_cast<long>(ps.n_real);
    long first = n;
#pragma omp parallel for schedule(static) reduction(min : first)
    for (long i = 0; i < n; ++i)
      if (!inside(ps, static_cast<std::size_t>(i))) first = std::min(first, i);
    return first < n ? first : -1;
  }

  // Scratch of build_halo (reused between steps): the runs of particles near the walls, the
  // particles looked at, and the index of each one's first ghost.
  mutable std::vector<std::pair<std::uint32_t, std::uint32_t>> runs_;
  mutable std::vector<std::uint32_t> near_;
  mutable std::vector<std::uint32_t> first_ghost_;

 private:
  // build_halo over the particles of `runs` (ranges of indices, increasing): a count per
  // particle, a prefix sum, then a parallel fill.
  void build_halo_of(const ParticleSet<D>& ps, double range, Halo<D>& halo,
                     std::span<const std::pair<std::uint32_t, std::uint32_t>> runs) const {
    std::vector<std::uint32_t>& near = near_;
    near.clear();
    for (const auto& [b, e] : runs)
      for (std::uint32_t i = b; i < e; ++i)
        near.push_back(i);
    const auto n = static_cast<long>(near.size());
    std::vector<std::uint32_t>& first = first_ghost_;
    first.resize(near.size() + 1);
#pragma omp parallel for schedule(static)
    for (long kk = 0; kk < n; ++kk) {
      const auto k = static_cast<std::size_t>(kk);
      first[k + 1] =
          static_cast<std::uint32_t>(for_each_image(ps.x[near[k]], range, [](auto&&) {}));
    }
    first[0] = 0;
    for (std::size_t k = 0; k < near.size(); ++k)
      first[k + 1] += first[k];
    auto& maps = halo.resize(first[near.size()]);
#pragma omp parallel for schedule(static)
    for (long kk = 0; kk < n; ++kk) {
      const auto k = static_cast<std::size_t>(kk);
      std::size_t g = first[k];
      for_each_image(ps.x[near[k]], range, [&](GhostMap<D> map) {
        map.source = near[k];
        maps[g++] = map;
      });
    }
  }

  // Whether a particle of [b, e) stands beyond the wall on `Side` of axis K: what put_back_at
  // acts on (a periodic side: any particle beyond it; a wall: within range beyond it).
  template <int K, int Side>
  bool any_across(const ParticleSet<D>& ps, std::size_t b, std::size_t e, double range) const {
    const double at = wall(K, Side);
    const double reach =
        acts_as(K, Side) == WallKind::periodic ? std::numeric_limits<double>::infinity() : range;
    const Vec<D>* __restrict x = ps.x.data();
    int any = 0;  // an int: GCC 12 left an | of bools scalar
#pragma omp simd reduction(| : any)
    for (std::size_t i = b; i < e; ++i) {
      const double depth = Side == 0 ? at - x[i][K] : x[i][K] - at;
      any |= (depth > 0.0) & (depth <= reach) ? 1 : 0;
    }
    return any != 0;
  }

  // put_back across both walls of axis K, the positions along it within [least, most];
  // whether either ran.
  template <int K>
  bool put_back_axis(ParticleSet<D>& ps, std::size_t b, std::size_t e, double range, double least,
                     double most) const {
    const bool low = put_back_at<K, 0>(ps, b, e, range, least < wall(K, 0));
    // A particle put back across the lower wall may now stand beyond the upper one (a box
    // narrower than the range): then the upper wall's scan is not skipped.
    const bool high = put_back_at<K, 1>(ps, b, e, range, low || most > wall(K, 1));
    return low || high;
  }

  // put_back across the wall on `Side` of axis K (compile-time, so that the particle loop
  // indexes fixed components and vectorises), unless no particle may stand beyond it
  // (!maybe_across); whether it ran.
  template <int K, int Side>
  bool put_back_at(ParticleSet<D>& ps, std::size_t b, std::size_t e, double range,
                   bool maybe_across) const {
    const WallKind w = acts_as(K, Side);
    if (w == WallKind::open || !maybe_across) return false;
    // The block is rewritten only when one of its particles has crossed this wall (a few
    // blocks a step): a read-only scan of x first, where the masked loops below read and write
    // x, v and v_half for every particle.
    if (!any_across<K, Side>(ps, b, e, range)) return false;
    if (w == WallKind::periodic) {
      // Re-injection (W 6.1): out of one end, in at the other, r + (x_i - l).
      const double at = wall(K, Side), length = hi[K] - lo[K];
      Vec<D>* __restrict x = ps.x.data();
#pragma omp simd
      for (std::size_t i = b; i < e; ++i) {
        const bool out = Side == 0 ? x[i][K] < at : x[i][K] > at;
        x[i][K] = out ? x[i][K] + (Side == 0 ? length : -length) : x[i][K];
      }
      return true;
    }
    const double at = wall(K, Side);
    const double u2 = 2.0 * wall_speed(K, Side);
    const bool no_slip = w == WallKind::no_slip;  // all components mirrored, else the normal one
    Vec<D>* __restrict x = ps.x.data();
    Vec<D>* __restrict v = ps.v.data();
    Vec<D>* __restrict v_half = ps.v_half.data();
#pragma omp simd
    for (std::size_t i = b; i < e; ++i) {
      const double depth = Side == 0 ? at - x[i][K] : x[i][K] - at;
      const bool across = depth > 0.0 && depth <= range;
      x[i][K] = across ? 2.0 * at - x[i][K] : x[i][K];
      for (int l = 0; l < D; ++l) {
        const bool mirror = across && (no_slip || l == K);
        const double vl = l == K ? -v[i][l] + u2 : -v[i][l];
        const double vhl = l == K ? -v_half[i][l] + u2 : -v_half[i][l];
        v[i][l] = mirror ? vl : v[i][l];
        v_half[i][l] = mirror ? vhl : v_half[i][l];
      }
    }
    return true;
  }

  std::array<std::array<double, 2>, D> place_{}, speed_{};
  bool placed_ = false;       // before set_time() the walls stand at lo, hi
  bool periodic_on_ = false;  // set_time's t >= periodic_from
};

}  // namespace flume
