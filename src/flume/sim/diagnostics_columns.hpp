// The columns of diagnostics.csv (spec/contract.md), in order: what a run writes
// (diagnostics.hpp) and what a case file may plot (validation.diagnostics_plots).
#pragma once

#include <string>
#include <vector>

namespace flume {

template <int D>
std::vector<std::string> diagnostics_columns() {
  std::vector<std::string> c{"time", "step", "dt", "particles", "mass", "momentum_x", "momentum_y"};
  if constexpr (D == 3) {
    c.insert(c.end(),
             {"momentum_z", "angular_momentum_x", "angular_momentum_y", "angular_momentum_z"});
  } else {
    c.push_back("angular_momentum");
  }
  c.insert(c.end(),
           {"kinetic_energy", "potential_energy", "internal_energy", "rho_min", "rho_max"});
  return c;
}

}  // namespace flume
