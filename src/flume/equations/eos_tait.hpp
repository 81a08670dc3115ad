// Tait equation of state, BL (60) / W (5.22), compression positive (methods.md erratum 1):
//   p = kappa [ (rho / rho0)^gamma - 1 ],   p_atm = 0.
// The bulk modulus kappa comes from a sound speed, kappa = rho0 c0^2 / gamma (BL (64), (66)).
#pragma once

#include <cmath>
#include <cstddef>

namespace flume {

struct TaitEos {
  double rho0 = 1000.0;  // reference density, kg/m^3
  double gamma = 7.0;    // exponent, -
  double kappa = 0.0;    // bulk modulus B, Pa

  double pressure(double rho) const { return pressure_of_power(power(rho / rho0)); }
  // p from (rho / rho0)^gamma: BL (60)'s bracket, one place for pressure() and the block pass.
  double pressure_of_power(double ratio_to_gamma) const { return kappa * (ratio_to_gamma - 1.0); }

  // a^gamma. A whole gamma (7 for water) by repeated squaring, a few products, where a pow call
  // took 7 % of a `standard` step (flume bench, 1e5 particles); the two differ by round-off.
  double power(double a) const {
    return whole_gamma() ? whole_power(a, static_cast<unsigned>(gamma)) : std::pow(a, gamma);
  }
  bool whole_gamma() const { return gamma >= 1.0 && gamma < 128.0 && gamma == std::floor(gamma); }
  // a^n for a whole n < 128: a fixed count of steps without a branch (a factor 1 is exact), so
  // that a pass over the particles vectorises: a^(bit 0) a^(2 bit 1) a^(4 bit 2) ...
  static double whole_power(double a, unsigned n) {
    double result = 1.0, square = a;
    for (unsigned k = 0; k < 7; ++k) {
      result *= ((n >> k) & 1u) != 0 ? square : 1.0;
      square *= square;
    }
    return result;
  }

  // p and c of the particles [b, e), the values of pressure(rho) and sound_speed(rho, p). The
  // test on gamma is taken once for the block, so that the loop vectorises: taken per particle
  // (in power) it kept the density's pass scalar, 3.2 % of a `standard` step (perf, 1e5).
  void pressure_and_sound_speed(const double* rho, double* p, double* c, std::size_t b,
                                std::size_t e) const {
    if (!whole_gamma()) {
      for (std::size_t i = b; i < e; ++i) {
        p[i] = pressure(rho[i]);
        c[i] = sound_speed(rho[i], p[i]);
      }
      return;
    }
    const auto n = static_cast<unsigned>(gamma);
#pragma omp simd
    for (std::size_t i = b; i < e; ++i) {
      const double pi = pressure_of_power(whole_power(rho[i] / rho0, n));
      p[i] = pi;
      c[i] = sound_speed(rho[i], pi);
    }
  }

  // c = sqrt(dp/drho) = c0 (rho/rho0)^((gamma-1)/2); BL (63) uses the reference value c0.
  double sound_speed(double rho) const {
    return std::sqrt(gamma * kappa / rho0 * std::pow(rho / rho0, gamma - 1.0));
  }
  // The same c from a pressure already computed, without a pow: since p + kappa =
  // kappa (rho/rho0)^gamma, dp/drho = gamma (p + kappa) / rho. For the pair loops.
  double sound_speed(double rho, double p) const {
    return std::sqrt(gamma * (p + kappa) / rho);
  }
  double reference_sound_speed() const {
    return std::sqrt(gamma * kappa / rho0);
  }

  // Stored elastic energy per unit mass, e(rho) = int_{rho0}^{rho} p / rho'^2 drho', the U of
  // BL (10)-(11) for this fluid: what the internal_energy diagnostic sums, so that kinetic +
  // potential + internal energy is conserved by an inviscid run.
  double specific_internal_energy(double rho) const {
    const double r0g = std::pow(rho0, gamma);
    return kappa / r0g * (std::pow(rho, gamma - 1.0) - std::pow(rho0, gamma - 1.0)) /
               (gamma - 1.0) +
           kappa * (1.0 / rho - 1.0 / rho0);
  }

  // The density at pressure p, the inverse of BL (60): rho0 (1 + p / kappa)^(1 / gamma).
  double density_at(double p) const {
    return rho0 * std::pow(1.0 + p / kappa, 1.0 / gamma);
  }

  // Density of still water at depth d below a free surface at p = 0: the column integrated,
  // dp/dd = rho(p) g with this EOS, whose solution is
  //   rho(d) = rho0 (1 + (gamma - 1) rho0 g d / (gamma kappa))^(1 / (gamma - 1))
  // (rho0 exp(rho0 g d / kappa) for gamma = 1). Taking p = rho0 g d instead leaves out the
  // weight of the compression, 0.25 % of the bed pressure of a column at 3.5 % compression.
  double hydrostatic_density(double g_times_depth) const {
    const double a = rho0 * g_times_depth / kappa;
    if (gamma == 1.0) return rho0 * std::exp(a);
    return rho0 * std::pow(1.0 + (gamma - 1.0) / gamma * a, 1.0 / (gamma - 1.0));
  }
};

}  // namespace flume
