// A breaking detector for a 2D wave tank (W 6.4.2, W-7 and W-8 of spec/cases.md; x along the
// tank, y up): a wave has broken once its front has overturned, i.e. once water stands over
// air. Measured on the main body of water (fluid_body.hpp: spray thrown off does not count):
// the particles are binned into columns two spacings wide, and in each column the particles'
// heights are sorted; a gap between two successive heights is air under water. The largest
// such gap over the tank is the probe's `overturn` (m). A settled or moving body of water has
// gaps of about a spacing (a column two spacings wide holds two particles per row, so even a
// disordered one rarely has a gap over two spacings); a plunging jet closes over a tube of air
// as tall as a good part of the wave. The wave is taken as broken the first time the gap
// exceeds `threshold` spacings (default 4): `broken_at`, the time it first did (0 before).
// This sees a plunging breaker as its jet leaves the face, slightly after the face passes
// vertical (the criterion of W 6.4.2); a spilling breaker, whose crest never overturns over a
// tube of air, is not seen by it. Where it broke, `broken_x` (m), is the centre of the column
// that held the gap at broken_at (0 before).
// A gap counts only with water below it too: its lower side at least two spacings above the
// column's lowest particle. A tube of air has water on both sides; a gap at the foot of a column
// has a wall under it, e.g. at the toe of a beach of repulsive particles, where the beach holds
// the water up to its reach off its plane (repulsive_walls.hpp) while the bed's mirror lets it
// sit half a spacing off: that pocket is not breaking.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "flume/core/particle_set.hpp"

namespace flume {

struct AirGap {
  double gap = 0.0;  // m
  double x = 0.0;    // m, the centre of the column that holds it
};

// The largest gap between successive heights of the particles of `in_body` within any column
// of width `column` (columns from x_lo) whose lower side stands at least `above` (m) over the
// column's lowest particle, and where it is (the first such column along x).
inline AirGap largest_air_gap(const ParticleSet<2>& ps, const std::vector<char>& in_body,
                              double x_lo, double column, double above = 0.0) {
  std::map<long, std::vector<double>> heights;
  for (std::size_t i = 0; i < ps.n_real; ++i)
    if (in_body[i])
      heights[static_cast<long>(std::floor((ps.x[i][0] - x_lo) / column))].push_back(ps.x[i][1]);
  AirGap largest;
  for (auto& [c, ys] : heights) {
    std::sort(ys.begin(), ys.end());
    for (std::size_t k = 1; k < ys.size(); ++k)
      if (ys[k - 1] - ys[0] >= above && ys[k] - ys[k - 1] > largest.gap)
        largest = {ys[k] - ys[k - 1], x_lo + (static_cast<double>(c) + 0.5) * column};
  }
  return largest;
}

class BreakingProbe {
 public:
  BreakingProbe(double spacing, double threshold) : dx_(spacing), threshold_(threshold) {}

  // {overturn (m), broken_at (s), broken_x (m); both 0 until it has broken} at time t.
  std::array<double, 3> operator()(const ParticleSet<2>& ps, const std::vector<char>& in_body,
                                   double x_lo, double t) {
    const AirGap g = largest_air_gap(ps, in_body, x_lo, 2.0 * dx_, 2.0 * dx_);
    if (broken_at_ == 0.0 && g.gap > threshold_ * dx_) {
      broken_at_ = t;
      broken_x_ = g.x;
    }
    return {g.gap, broken_at_, broken_x_};
  }

  std::vector<double> state() const { return {broken_at_, broken_x_}; }
  void restore(const std::vector<double>& s) {
    if (s.size() >= 1) broken_at_ = s[0];
    if (s.size() >= 2) broken_x_ = s[1];
  }

 private:
  double dx_, threshold_;
  double broken_at_ = 0.0;
  double broken_x_ = 0.0;
};

}  // namespace flume
