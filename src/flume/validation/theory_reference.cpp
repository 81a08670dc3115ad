#include "flume/validation/theory_reference.hpp"

#include <fmt/format.h>

#include <cmath>

#include "flume/core/error.hpp"
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

}  // namespace

io::CsvData curve_reference(const CaseSpec& spec, const CurveCheck& check) {
  if (check.theory.empty()) return io::read_csv(check.reference);
  if (check.theory == "elliptical_drop") return elliptical_drop_reference(spec);
  throw InputError(
      fmt::format("{}: unknown reference theory:{}", spec.file.string(), check.theory));
}

}  // namespace flume
