#include "flume/validation/curve_compare.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flume {

double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  if (xs.empty() || !(x >= xs.front() && x <= xs.back()))
    throw std::out_of_range("interpolate: x outside the series");
  auto it = std::upper_bound(xs.begin(), xs.end(), x);
  if (it == xs.end()) return ys.back();
  const auto k = static_cast<std::size_t>(it - xs.begin());
  if (k == 0) return ys.front();
  const double w = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
  return ys[k - 1] + w * (ys[k] - ys[k - 1]);
}

std::vector<CurvePoint> compare_curve(const std::vector<double>& t, const std::vector<double>& y,
                                      const std::vector<double>& ref_x,
                                      const std::vector<double>& ref_y, double time_scale,
                                      double value_scale, bool absolute) {
  std::vector<double> xs, ys;
  for (std::size_t k = 0; k < t.size(); ++k) {
    xs.push_back(t[k] / time_scale);
    ys.push_back(y[k] / value_scale);
  }
  std::vector<CurvePoint> out;
  for (std::size_t k = 0; k < ref_x.size(); ++k) {
    if (xs.empty() || !(ref_x[k] >= xs.front() && ref_x[k] <= xs.back())) continue;
    CurvePoint p;
    p.x = ref_x[k];
    p.reference = ref_y[k];
    p.value = interpolate(xs, ys, p.x);
    // Relative error; absolute when asked, or where the reference is zero (no relative scale).
    const double diff = std::abs(p.value - p.reference);
    p.error = !absolute && p.reference != 0.0 ? diff / std::abs(p.reference) : diff;
    out.push_back(p);
  }
  return out;
}

}  // namespace flume
