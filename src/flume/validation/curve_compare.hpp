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

// Linear interpolation of (xs, ys) at x, xs ascending; x must lie within [xs.front(), xs.back()].
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x);

}  // namespace flume
