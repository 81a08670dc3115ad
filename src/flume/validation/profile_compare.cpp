#include "flume/validation/profile_compare.hpp"

#include <cmath>
#include <vector>

namespace flume {

ShockTube shock_tube(const CaseSpec& spec) {
  const auto state = [&](const FluidBlock& b) {
    const double rho = b.density > 0.0 ? b.density : spec.rho0;
    return GasState{rho, b.velocity.at(0), (spec.gamma - 1.0) * rho * b.internal_energy};
  };
  return ShockTube{RiemannSolution(state(spec.blocks.at(0)), state(spec.blocks.at(1)), spec.gamma),
                   spec.blocks.at(0).max.at(0), spec.end_time};
}

namespace {
double field_of(const GasState& w, const std::string& field) {
  return field == "rho" ? w.rho : field == "p" ? w.p : w.u;
}
}  // namespace

double profile_l1_error(const ShockTube& tube, const io::CsvData& profile,
                        const std::string& field) {
  const auto x = profile.column("x"), f = profile.column(field == "u" ? "u" : field);
  double diff = 0.0, norm = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double exact = field_of(tube.at(x[k]), field);
    diff += std::abs(f[k] - exact);
    norm += std::abs(exact);
  }
  return norm > 0.0 ? diff / norm : HUGE_VAL;
}

void write_exact_profile(const ShockTube& tube, double x0, double x1, int n,
                         const std::filesystem::path& file) {
  io::CsvTable table(file, {"x", "rho", "p", "u"});
  for (int k = 0; k < n; ++k) {
    const double x = x0 + (x1 - x0) * k / (n - 1);
    const GasState w = tube.at(x);
    table.add_row(std::vector<double>{x, w.rho, w.p, w.u});
  }
  table.flush();
}

}  // namespace flume
