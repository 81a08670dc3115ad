// The equation of state of a case, chosen by name ([eos] kind): Tait for a liquid, BL (60) /
// W (5.22), or the ideal gas p = (gamma - 1) rho e of W's shock tube. One small value type:
// the loops over the particles ask for the kind once and run the concrete equation's loop
// (common_steps.hpp), so that each stays a vectorised loop without a branch per particle.
#pragma once

#include "flume/equations/eos_ideal_gas.hpp"
#include "flume/equations/eos_tait.hpp"

namespace flume {

enum class EosKind { tait, ideal_gas };

struct Eos {
  EosKind kind = EosKind::tait;
  double rho0 = 1000.0;  // reference density, kg/m^3 (Tait; a gas's nominal density)
  double gamma = 7.0;    // Tait exponent, or the gas's ratio of specific heats, -
  double kappa = 0.0;    // Tait bulk modulus B, Pa (unused by a gas)

  TaitEos tait() const { return TaitEos{rho0, gamma, kappa}; }
  IdealGasEos gas() const { return IdealGasEos{gamma}; }
  bool is_gas() const { return kind == EosKind::ideal_gas; }

  // p(rho, e): e is ignored by Tait (a barotropic liquid).
  double pressure(double rho, double e) const {
    return is_gas() ? gas().pressure(rho, e) : tait().pressure(rho);
  }
  // The local sound speed from a pressure already computed.
  double sound_speed(double rho, double p) const {
    return is_gas() ? gas().sound_speed(rho, p) : tait().sound_speed(rho, p);
  }
  // Tait's c0 = sqrt(gamma kappa / rho0), the speed of BL (63); 0 for a gas, whose time step
  // takes each particle's own sound speed (W (3.88), time_step.hpp).
  double reference_sound_speed() const { return is_gas() ? 0.0 : tait().reference_sound_speed(); }
  // Specific internal energy: the gas's own e, or the liquid's stored elastic energy e(rho).
  double specific_internal_energy(double rho, double e) const {
    return is_gas() ? e : tait().specific_internal_energy(rho);
  }
  // The liquid's density at pressure p (the case reader starts no gas block from a pressure).
  double density_at_pressure(double p) const { return tait().density_at(p); }
  // Density of still fluid at depth d (Tait's integrated column); a gas block starts uniform at
  // its own density (the case reader refuses a hydrostatic gas block).
  double hydrostatic_density(double g_times_depth) const {
    return is_gas() ? rho0 : tait().hydrostatic_density(g_times_depth);
  }
};

}  // namespace flume
