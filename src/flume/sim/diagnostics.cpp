#include "flume/sim/diagnostics.hpp"

#include <algorithm>
#include <limits>

namespace flume {

template <int D>
std::vector<double> diagnostics_row(const ParticleSet<D>& ps, const Physics<D>& phys, double time,
                                    long step, double dt) {
  double mass = 0.0, ke = 0.0, pe = 0.0, ie = 0.0;
  double rho_min = std::numeric_limits<double>::max(), rho_max = 0.0;
  Vec<D> mom;
  Vec<3> ang;
  for (std::size_t i = 0; i < ps.n_real; ++i) {
    const double m = ps.m[i];
    mass += m;
    mom += ps.v_half[i] * m;
    if constexpr (D == 2) {
      ang[2] += m * cross_z(ps.x[i], ps.v_half[i]);
    } else {
      const auto& x = ps.x[i];
      const auto& v = ps.v_half[i];
      ang[0] += m * (x[1] * v[2] - x[2] * v[1]);
      ang[1] += m * (x[2] * v[0] - x[0] * v[2]);
      ang[2] += m * (x[0] * v[1] - x[1] * v[0]);
    }
    ke += 0.5 * m * norm2(ps.v[i]);
    pe -= m * dot(phys.gravity, ps.x[i]);
    ie += m * phys.eos.specific_internal_energy(ps.rho[i], ps.uses(kFieldEnergy) ? ps.e[i] : 0.0);
    rho_min = std::min(rho_min, ps.rho[i]);
    rho_max = std::max(rho_max, ps.rho[i]);
  }
  std::vector<double> row{time, static_cast<double>(step), dt, static_cast<double>(ps.n_real),
                          mass};
  for (int k = 0; k < D; ++k)
    row.push_back(mom[k]);
  if constexpr (D == 3) {
    row.insert(row.end(), {ang[0], ang[1], ang[2]});
  } else {
    row.push_back(ang[2]);
  }
  row.insert(row.end(), {ke, pe, ie, rho_min, rho_max});
  return row;
}

template std::vector<double> diagnostics_row<2>(const ParticleSet<2>&, const Physics<2>&, double,
                                                long, double);
template std::vector<double> diagnostics_row<3>(const ParticleSet<3>&, const Physics<3>&, double,
                                                long, double);

}  // namespace flume
