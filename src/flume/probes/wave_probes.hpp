// Measurements of a 2D wave tank (W 6.4; x along the tank, y up), all from the depth profile of
// water_depth.hpp:
// - the crest: where the depth is highest (highest_crest) and its amplitude above the still
//   depth H, A = eta_max - H (W Fig 6.9). In a periodic tank the crest's position is unwrapped:
//   each reading is taken as the image x + m L nearest the previous one, so a wave that has
//   gone round the tank n times reads n L further on and its speed is the slope of crest_x
//   (the tracker's last position is its state, kept in a checkpoint); and the crest's centre,
//   the centroid of its upper half (crest_centre), a steadier position where the top is flat;
// - wave gauges: the surface elevation eta(x_g) - H at fixed places, as a resistance gauge reads
//   it (the mean of its column).
// Speeds are taken from crest_x by validation's least-squares slope over a window (W reads them
// off Fig 6.11(b) over t = 3-7 s).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "flume/probes/water_depth.hpp"
#include "flume/theory/solitary_wave.hpp"

namespace flume {

struct WaveReading {
  double crest_x = 0.0;          // m along the tank, unwrapped in a periodic tank
  double crest_amplitude = 0.0;  // m above the still depth
  double crest_centre_x = 0.0;  // m: the centre of the crest's upper half (crest_centre), unwrapped
  double crest2_x = 0.0;        // the second crest (when asked for), m
  double crest2_amplitude = 0.0;
  std::vector<double> gauges;  // m above the still depth, one per gauge
};

class WaveProbe {
 public:
  // second_separation > 0: also track the highest other crest at least that far (m) from the
  // highest (two waves in one tank, W 6.4.2's interaction).
  WaveProbe(double still_depth, std::vector<double> gauges, double second_separation = 0.0)
      : still_(still_depth), gauges_(std::move(gauges)), separation_(second_separation) {}

  WaveReading operator()(const DepthProfile& d) {
    WaveReading r;
    const Crest c = highest_crest(d);
    r.crest_x = unwrapped(d, c.x, last_);
    r.crest_amplitude = c.height - still_;
    // Within a wave's width of the crest: unwrapped as the crest is.
    r.crest_centre_x = r.crest_x + (crest_centre(d, c, still_) - c.x);
    if (separation_ > 0.0) {
      const Crest c2 = highest_crest_away_from(d, c.x, separation_);
      r.crest2_x = std::isfinite(c2.x) ? unwrapped(d, c2.x, last2_) : c2.x;
      r.crest2_amplitude = c2.height - still_;
    }
    for (const double xg : gauges_)
      r.gauges.push_back(d.at(xg) - still_);
    return r;
  }

  // The trackers' last unwrapped crest positions (a checkpoint's probe state): empty before
  // the first reading.
  std::vector<double> state() const {
    std::vector<double> s;
    if (last_) s.push_back(*last_);
    if (last_ && last2_) s.push_back(*last2_);
    return s;
  }
  void restore(const std::vector<double>& s) {
    if (!s.empty()) last_ = s[0];
    if (s.size() > 1) last2_ = s[1];
  }

 private:
  // x taken as the image x + m L nearest the tracker's last position (a periodic tank).
  static double unwrapped(const DepthProfile& d, double x, std::optional<double>& last) {
    if (d.periodic && last) {
      const double L = d.length();
      x += L * std::round((*last - x) / L);
    }
    last = x;
    return x;
  }

  double still_;
  std::vector<double> gauges_;
  double separation_;
  std::optional<double> last_, last2_;
};

// A solitary wave meeting a plane beach of slope s whose toe stands at x_toe (W 6.4.2, W-8 of
// spec/cases.md): its incident amplitude A, the crest's amplitude at the last reading before the
// crest came within one still depth H of the toe (kept from then on: nearer, the wave shoals and
// meets what the beach reflects; over the beach the wall's stand-off makes the surface read low,
// water_depth.hpp), and Grilli's prediction for it:
// breaking if A / H > 16.9 s^2 (W (6.19)), S0 = 1.521 s / sqrt(A / H) (W (6.20)), whose
// Table 6.2 ranges give the breaker type (theory/solitary_wave.hpp).
class ShoalingProbe {
 public:
  ShoalingProbe(double still_depth, double slope, double toe)
      : still_(still_depth), slope_(slope), toe_(toe) {}

  // {incident_amplitude (m), grilli_s0 (-), grilli_breaks (1 or 0)} after the crest reading.
  std::array<double, 3> operator()(double crest_x, double crest_amplitude) {
    if (crest_x >= toe_ - still_) passed_ = true;
    if (!passed_) incident_ = crest_amplitude;
    if (!(incident_ > 0.0)) return {0.0, 0.0, 0.0};
    const double ratio = incident_ / still_;
    return {incident_, grilli_s0(ratio, slope_), grilli_breaks(ratio, slope_) ? 1.0 : 0.0};
  }

  std::vector<double> state() const { return {incident_, passed_ ? 1.0 : 0.0}; }
  void restore(const std::vector<double>& s) {
    if (s.size() == 2) {
      incident_ = s[0];
      passed_ = s[1] != 0.0;
    }
  }

 private:
  double still_, slope_, toe_;
  double incident_ = 0.0;
  bool passed_ = false;  // the crest has reached the toe: the incident amplitude is kept
};

// Still water (W 6.5, W-3 of spec/cases.md): a tank at rest under gravity.
struct StillWaterReading {
  double bed_pressure = 0.0;       // Pa
  double water_level = 0.0;        // m above the bed
  double density_deviation = 0.0;  // max |rho - rho0| / rho0 over the particles
};

// - bed_pressure: the pressure at the bed as a gauge reads it: each particle's pressure in the
//   four bottom rows (y - bed < 4 dx) and x_lo < x < x_hi (a case reads the middle 80 % of the
//   tank's width, or the span it names: the flat bed before a beach), extrapolated to
//   the bed with the hydrostatic gradient (p + rho0 g (y - bed)), averaged. An even number of
//   rows: the pressure of a column carries a small odd-even row mode that a pair of rows cancels
//   (tests/properties/test_hydrostatic_tank.cpp says more).
// - water_level: twice the mean height of the particles above the bed, the height of the surface
//   of a level layer on a lattice (n rows at (j + 1/2) dx have mean height n dx / 2); a layer
//   that is compressed, or swells, reads lower or higher. Meaningful for still water only.
// - density_deviation: the largest |rho_i - rho0| / rho0.
template <int D>
StillWaterReading read_still_water(const ParticleSet<D>& ps, double x_lo, double x_hi, double bed,
                                   double rho0, double g, double dx) {
  StillWaterReading r;
  double p_sum = 0.0, y_sum = 0.0;
  long p_count = 0;
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    const double y = ps.x[i][D - 1] - bed;
    y_sum += y;
    r.density_deviation = std::max(r.density_deviation, std::abs(ps.rho[i] - rho0) / rho0);
    if (y < 4.0 * dx && ps.x[i][0] > x_lo && ps.x[i][0] < x_hi) {
      p_sum += ps.p[i] + rho0 * g * y;
      ++p_count;
    }
  }
  r.bed_pressure = p_count ? p_sum / static_cast<double>(p_count) : 0.0;
  r.water_level = ps.n_real ? 2.0 * y_sum / static_cast<double>(ps.n_real) : 0.0;
  return r;
}

}  // namespace flume
