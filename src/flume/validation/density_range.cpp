#include "flume/validation/density_range.hpp"

#include <algorithm>
#include <stdexcept>

namespace flume {

DensityRange density_range(const io::CsvData& diagnostics, double rho0) {
  if (!(rho0 > 0.0)) throw std::invalid_argument("density_range: rho0 must be positive");
  const auto lo = diagnostics.column("rho_min"), hi = diagnostics.column("rho_max");
  if (lo.empty()) throw std::invalid_argument("density_range: diagnostics.csv has no rows");
  return DensityRange{(*std::max_element(hi.begin(), hi.end()) - rho0) / rho0,
                      (*std::min_element(lo.begin(), lo.end()) - rho0) / rho0};
}

}  // namespace flume
