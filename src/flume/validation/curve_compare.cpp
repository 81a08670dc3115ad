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

namespace {

double mean_of(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v)
    s += x;
  return s / static_cast<double>(v.size());
}

// Least-squares slope of (x, y).
double slope_of(const std::vector<double>& x, const std::vector<double>& y) {
  const double mx = mean_of(x), my = mean_of(y);
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxy += (x[k] - mx) * (y[k] - my);
    sxx += (x[k] - mx) * (x[k] - mx);
  }
  return sxy / sxx;
}

// The least-squares line of (x, y) at x = at.
double line_at(const std::vector<double>& x, const std::vector<double>& y, double at) {
  return mean_of(y) + slope_of(x, y) * (at - mean_of(x));
}

}  // namespace

double mean_period(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() < 2) return std::nan("");
  const double m = mean_of(y);
  double first = 0.0, last = 0.0;
  long crossings = 0;
  for (std::size_t k = 1; k < x.size(); ++k)
    if (y[k - 1] - m < 0.0 && y[k] - m >= 0.0) {
      const double at = x[k - 1] + (m - y[k - 1]) / (y[k] - y[k - 1]) * (x[k] - x[k - 1]);
      if (crossings == 0) first = at;
      last = at;
      ++crossings;
    }
  return crossings < 2 ? std::nan("") : (last - first) / static_cast<double>(crossings - 1);
}

double window_statistic(const std::vector<double>& t, const std::vector<double>& y,
                        CurveStatistic statistic, double from, double to, double at) {
  std::vector<double> xs, ys;
  for (std::size_t k = 0; k < t.size() && k < y.size(); ++k)
    if (t[k] >= from && t[k] <= to) {
      xs.push_back(t[k]);
      ys.push_back(y[k]);
    }
  if (xs.size() < 2 || statistic == CurveStatistic::pointwise) return std::nan("");
  if (statistic == CurveStatistic::max) return *std::max_element(ys.begin(), ys.end());
  if (statistic == CurveStatistic::line_at) return line_at(xs, ys, at);
  if (statistic == CurveStatistic::period) return mean_period(xs, ys);
  return statistic == CurveStatistic::mean ? mean_of(ys) : slope_of(xs, ys);
}

std::vector<CurvePoint> compare_over_window(
    const std::vector<double>& t, const std::vector<double>& y, const std::vector<double>& ref_x,
    const std::vector<double>& ref_y, double time_scale, double value_scale, bool absolute,
    CurveStatistic statistic, double from, double to, double at) {
  std::vector<double> rx, ry;
  for (std::size_t k = 0; k < ref_x.size(); ++k)
    if (ref_x[k] >= from && ref_x[k] <= to) {
      rx.push_back(ref_x[k]);
      ry.push_back(ref_y[k]);
    }
  auto points = compare_curve(t, y, rx, ry, time_scale, value_scale, absolute);
  if (statistic == CurveStatistic::pointwise) return points;
  // Only a window the run covered entirely is summarised: a run that stopped early must not
  // pass on the part it reached.
  if (points.size() < 2 || points.size() != rx.size()) return {};
  std::vector<double> xs, fv, rv;
  for (const auto& p : points) {
    xs.push_back(p.x);
    fv.push_back(p.value);
    rv.push_back(p.reference);
  }
  CurvePoint out;
  out.x = xs.back();
  if (statistic == CurveStatistic::period) {
    std::vector<double> ts, ys;
    for (std::size_t k = 0; k < t.size() && k < y.size(); ++k)
      if (t[k] / time_scale >= from && t[k] / time_scale <= to) {
        ts.push_back(t[k] / time_scale);
        ys.push_back(y[k] / value_scale);
      }
    out.value = mean_period(ts, ys);
    out.reference = mean_of(rv);
    if (!std::isfinite(out.value)) return {};  // fewer than two crossings: no period measured
  } else if (statistic == CurveStatistic::mean) {
    out.value = mean_of(fv);
    out.reference = mean_of(rv);
  } else if (statistic == CurveStatistic::max) {
    out.value = *std::max_element(fv.begin(), fv.end());
    out.reference = *std::max_element(rv.begin(), rv.end());
  } else if (statistic == CurveStatistic::line_at) {
    out.value = line_at(xs, fv, at);
    out.reference = line_at(xs, rv, at);
  } else {
    out.value = slope_of(xs, fv);
    out.reference = slope_of(xs, rv);
  }
  const double diff = std::abs(out.value - out.reference);
  out.error = !absolute && out.reference != 0.0 ? diff / std::abs(out.reference) : diff;
  return {out};
}

}  // namespace flume
