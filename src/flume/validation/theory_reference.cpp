#include "flume/validation/theory_reference.hpp"

#include <fmt/format.h>

#include <cmath>

#include "flume/core/error.hpp"
#include "flume/theory/bore.hpp"
#include "flume/theory/elliptical_drop.hpp"

namespace flume {

namespace {

io::CsvData elliptical_drop_reference(const CaseSpec& spec) {
  const FluidBlock& b = spec.blocks.front();
  const auto fail = [&](const std::string& what) {
    throw InputError(
        fmt::format("{}: validation.curves: theory:elliptical_drop: {}", spec.file.string(), what));
  };
  if (spec.dimension != 2 || b.shape != "ellipsoid") fail("needs a 2D disc as the first block");
  const double rx = 0.5 * (b.max[0] - b.min[0]), ry = 0.5 * (b.max[1] - b.min[1]);
  if (std::abs(rx - ry) > 1e-12 * ry) fail("needs a circle (equal semi-axes) at the start");
  const auto& G = b.velocity_gradient;
  if (G[1] != 0.0 || G[2] != 0.0 || G[0] != -G[3])
    fail("needs the velocity gradient diag(-A0, A0) (BL 5.2)");
  io::CsvData d;
  d.columns = {"t", "a", "b"};
  const int n = 40;
  for (int k = 1; k <= n; ++k) {
    const double t = spec.end_time * k / n;
    const auto s = elliptical_drop_exact(G[3], ry, t);
    d.rows.push_back({t, s.a, s.b});
  }
  return d;
}

// BL (67)-(68) for the first block: depth h0, speed v0 toward the x_min wall (-velocity[0]),
// gravity |g|. The front runs from the wall at v_s from t = 0; the height is h throughout.
io::CsvData bore_reference(const CaseSpec& spec) {
  const FluidBlock& b = spec.blocks.front();
  const auto fail = [&](const std::string& what) {
    throw InputError(
        fmt::format("{}: validation.curves: theory:bore: {}", spec.file.string(), what));
  };
  const auto d = static_cast<std::size_t>(spec.dimension);
  const double h0 = b.max[d - 1] - b.min[d - 1];
  const double v0 = -b.velocity[0];
  const double g = -spec.gravity[d - 1];
  if (!(v0 > 0.0)) fail("needs the first block moving toward the x_min wall (velocity[0] < 0)");
  if (!(g > 0.0)) fail("needs gravity pointing down the last axis");
  const auto sol = bore_solution(h0, v0, g);
  io::CsvData out;
  out.columns = {"t", "front", "height"};
  // At the output times, so that a window's ends are points of it.
  const auto n = static_cast<long>(std::floor(spec.end_time / spec.output_interval + 1e-9));
  for (long k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) * spec.output_interval;
    out.rows.push_back({t, sol.v_s * t, sol.h});
  }
  return out;
}

}  // namespace

io::CsvData curve_reference(const CaseSpec& spec, const CurveCheck& check) {
  if (check.theory.empty()) return io::read_csv(check.reference);
  if (check.theory == "elliptical_drop") return elliptical_drop_reference(spec);
  if (check.theory == "bore") return bore_reference(spec);
  throw InputError(
      fmt::format("{}: unknown reference theory:{}", spec.file.string(), check.theory));
}

}  // namespace flume
