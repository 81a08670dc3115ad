// Comparing a probe's time series with a reference curve: the probe is interpolated linearly in
// time at each reference point inside the simulated window, and the error is relative.
#pragma once

#include <string>
#include <vector>

namespace flume {

struct CurvePoint {
  double x = 0.0;          // reference abscissa (dimensionless time)
  double reference = 0.0;  // reference value
  double value = 0.0;      // flume's value, same scaling
  double error = 0.0;      // |value - reference| / |reference| (absolute if reference is 0)
};

// t, y: the probe series (seconds, metres). ref_x, ref_y: the reference, dimensionless.
// time_scale and value_scale turn flume's t and y into the reference's scaling. With `absolute`
// the error is |value - reference| in the reference's units instead of relative.
std::vector<CurvePoint> compare_curve(const std::vector<double>& t, const std::vector<double>& y,
                                      const std::vector<double>& ref_x,
                                      const std::vector<double>& ref_y, double time_scale,
                                      double value_scale, bool absolute = false);

// How a probe is compared with its reference over a window [from, to] of the reference's x.
enum class CurveStatistic {
  pointwise,  // at every reference point (compare_curve)
  mean,       // the mean of the values at the reference points
  slope,      // their least-squares slope against x (a speed from a position)
  max,        // the largest of them (a deviation that must stay within a bound)
  line_at,    // their least-squares line's value at a given x (a crest's place extrapolated)
  period,     // the mean period of the probe's oscillation about its mean over the window
};

// Compares the statistic of flume's values (interpolated at the reference points inside the
// window and the simulated time) with the same statistic of the reference. pointwise gives one
// point per reference point; the others give one point at the window's last reference point
// (empty if fewer than two points fall inside). `at` is line_at's x. period takes flume's own
// samples inside the window (every one, not only those at the reference points: a crossing is
// placed between two samples), in the reference's x, against the reference's mean.
std::vector<CurvePoint> compare_over_window(
    const std::vector<double>& t, const std::vector<double>& y, const std::vector<double>& ref_x,
    const std::vector<double>& ref_y, double time_scale, double value_scale, bool absolute,
    CurveStatistic statistic, double from, double to, double at = 0.0);

// "mean", "slope", "max", "line_at", "period" or "pointwise".
inline const char* statistic_name(CurveStatistic s) {
  return s == CurveStatistic::mean      ? "mean"
         : s == CurveStatistic::slope   ? "slope"
         : s == CurveStatistic::max     ? "max"
         : s == CurveStatistic::line_at ? "line_at"
         : s == CurveStatistic::period  ? "period"
                                        : "pointwise";
}

// The mean period of the samples (x, y) about their mean: the span from the first to the last
// upward crossing of the mean (each placed by linear interpolation between the samples around
// it) over the number of periods between them. NaN with fewer than two crossings.
double mean_period(const std::vector<double>& x, const std::vector<double>& y);

// The statistic of the samples (t, y) with t in [from, to] (line_at: the least-squares line's
// value at t = at); NaN when fewer than two fall inside (pointwise is not a statistic: NaN).
double window_statistic(const std::vector<double>& t, const std::vector<double>& y,
                        CurveStatistic statistic, double from, double to, double at = 0.0);

// Linear interpolation of (xs, ys) at x, xs ascending; x must lie within [xs.front(), xs.back()].
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x);

}  // namespace flume
