// Exact solution of the Riemann problem for the one-dimensional Euler equations of an ideal
// (polytropic) gas, p = (gamma - 1) rho e, following the construction of E. F. Toro, "Riemann
// Solvers and Numerical Methods for Fluid Dynamics", 3rd ed., Springer (2009), chapter 4. It is
// the reference for the SPH shock tube: the density, velocity and pressure profiles at a time t
// after a diaphragm at x0 separating two uniform states at rest (or not) is removed.
//
// The solution is self-similar, W(x, t) = W((x - x0) / t), and consists of four constant states
//   W_L | left wave | W*L | contact | W*R | right wave | W_R
// where each outer wave is a shock (p* > p_K) or a rarefaction fan (p* <= p_K), and pressure and
// velocity are continuous across the contact. The star pressure p* is the single root of
//   f(p) = f_L(p) + f_R(p) + (u_R - u_L)                        (Toro (2009) section 4.2)
// which is monotone increasing and concave in p, so Newton's method converges from a good guess
// (section 4.3); here it is additionally kept inside a bracket so that it cannot leave p > 0.
//
// Vacuum: if (2 / (gamma - 1)) (a_L + a_R) <= u_R - u_L the two rarefactions separate and a vacuum
// opens between them (Toro (2009) section 4.6); f has no positive root. That solution is not
// implemented: the constructor throws std::domain_error instead of returning something wrong.
// Initial states must have rho > 0 and p > 0 (std::invalid_argument otherwise).
#pragma once

#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>

namespace flume {

// Primitive variables of the gas: density, velocity, pressure.
struct GasState {
  double rho = 0.0;
  double u = 0.0;
  double p = 0.0;
};

// Sound speed of an ideal gas, a = sqrt(gamma p / rho).
inline double sound_speed(const GasState& w, double gamma) {
  return std::sqrt(gamma * w.p / w.rho);
}

// Specific internal energy from the ideal-gas law, e = p / ((gamma - 1) rho).
inline double specific_internal_energy(const GasState& w, double gamma) {
  return w.p / ((gamma - 1.0) * w.rho);
}

// Pressure of an ideal gas with density rho and specific internal energy e.
inline double ideal_gas_pressure(double rho, double e, double gamma) {
  return (gamma - 1.0) * rho * e;
}

class RiemannSolution {
 public:
  RiemannSolution(GasState left, GasState right, double gamma)
      : left_(left), right_(right), gamma_(gamma) {
    check_inputs();
    a_left_ = sound_speed(left_, gamma_);
    a_right_ = sound_speed(right_, gamma_);
    // Vacuum generation (Toro (2009) section 4.6): the largest velocity jump two rarefactions can
    // absorb is that at p* = 0, where f(0) = -(2 / (gamma - 1)) (a_L + a_R) + (u_R - u_L). If
    // f(0) >= 0 there is no positive star pressure and the gas separates.
    const double critical_velocity_jump = 2.0 / (gamma_ - 1.0) * (a_left_ + a_right_);
    if (critical_velocity_jump <= right_.u - left_.u) {
      throw std::domain_error(
          "RiemannSolution: the initial states generate a vacuum ((2/(gamma-1))(a_L + a_R) = " +
          std::to_string(critical_velocity_jump) + " <= u_R - u_L = " +
          std::to_string(right_.u - left_.u) + "); the vacuum solution is not implemented");
    }
    solve_star_pressure();
    const Branch fl = wave_function(p_star_, left_, a_left_);
    const Branch fr = wave_function(p_star_, right_, a_right_);
    // Star velocity from the two wave curves (Toro (2009) section 4.2): u* = u_L - f_L(p*) and
    // u* = u_R + f_R(p*); their mean cancels most of the residual of the root.
    u_star_ = 0.5 * (left_.u + right_.u) + 0.5 * (fr.f - fl.f);
    rho_star_left_ = star_density(left_);
    rho_star_right_ = star_density(right_);
  }

  double gamma() const { return gamma_; }
  GasState left() const { return left_; }
  GasState right() const { return right_; }

  double p_star() const { return p_star_; }
  double u_star() const { return u_star_; }
  double rho_star_left() const { return rho_star_left_; }
  double rho_star_right() const { return rho_star_right_; }
  // Newton (or safeguard bisection) steps taken for p*; a few for a quadratically converging
  // Newton, so a large count reveals a wrong derivative even though the root would be right.
  int iterations() const { return iterations_; }

  // Wave type: a compressive wave (p* > p_K) is a shock, an expansive one a rarefaction.
  bool left_is_shock() const { return p_star_ > left_.p; }
  bool right_is_shock() const { return p_star_ > right_.p; }

  // Shock speeds from the mass jump condition, written with the pressure ratio (Toro (2009)
  // section 4.4): S_L = u_L - a_L Q_L, S_R = u_R + a_R Q_R,
  // Q_K = sqrt((gamma + 1)/(2 gamma) p*/p_K + (gamma - 1)/(2 gamma)). Only meaningful for a shock.
  double left_shock_speed() const { return left_.u - a_left_ * shock_mach(left_); }
  double right_shock_speed() const { return right_.u + a_right_ * shock_mach(right_); }

  // Speeds bounding each outer wave. The head is the edge facing the undisturbed state, the tail
  // the edge facing the star region; for a shock both are the shock speed.
  double left_head_speed() const {
    return left_is_shock() ? left_shock_speed() : left_.u - a_left_;
  }
  double left_tail_speed() const {
    return left_is_shock() ? left_shock_speed() : u_star_ - star_sound_speed(left_, a_left_);
  }
  double right_head_speed() const {
    return right_is_shock() ? right_shock_speed() : right_.u + a_right_;
  }
  double right_tail_speed() const {
    return right_is_shock() ? right_shock_speed() : u_star_ + star_sound_speed(right_, a_right_);
  }

  // The state at similarity variable s = (x - x0) / t (Toro (2009) section 4.5). At s = u* the
  // contact itself, the left star state is returned; at the exact position of a shock, the
  // undisturbed state.
  GasState sample(double s) const {
    if (s <= u_star_) {
      if (left_is_shock()) {
        return s <= left_shock_speed() ? left_ : GasState{rho_star_left_, u_star_, p_star_};
      }
      if (s <= left_head_speed()) return left_;
      if (s >= left_tail_speed()) return GasState{rho_star_left_, u_star_, p_star_};
      return inside_left_fan(s);
    }
    if (right_is_shock()) {
      return s >= right_shock_speed() ? right_ : GasState{rho_star_right_, u_star_, p_star_};
    }
    if (s >= right_head_speed()) return right_;
    if (s <= right_tail_speed()) return GasState{rho_star_right_, u_star_, p_star_};
    return inside_right_fan(s);
  }

  // The state at position x and time t >= 0 for a diaphragm at x0. At t = 0 the initial data
  // (left state for x < x0), since the similarity variable is undefined there.
  GasState at(double x, double t, double x0) const {
    if (!(t >= 0.0)) throw std::invalid_argument("RiemannSolution::at: t must be >= 0");
    if (t == 0.0) return x < x0 ? left_ : right_;
    return sample((x - x0) / t);
  }

 private:
  struct Branch {
    double f;   // f_K(p)
    double df;  // d f_K / dp
  };

  void check_inputs() const {
    if (!(gamma_ > 1.0) || !std::isfinite(gamma_)) {
      throw std::invalid_argument("RiemannSolution: gamma must be finite and > 1");
    }
    for (const GasState& w : {left_, right_}) {
      if (!(w.rho > 0.0) || !(w.p > 0.0) || !std::isfinite(w.rho) || !std::isfinite(w.p) ||
          !std::isfinite(w.u)) {
        throw std::invalid_argument(
            "RiemannSolution: initial states need finite rho > 0, p > 0 and finite u");
      }
    }
  }

  // One half of the pressure function, f_K(p), which gives the velocity change across the wave
  // that connects W_K to a star state of pressure p (Toro (2009) section 4.2), with its derivative.
  Branch wave_function(double p, const GasState& w, double a) const {
    if (p > w.p) {
      // Shock branch, from the Rankine-Hugoniot conditions: f_K = (p - p_K) sqrt(A_K/(p + B_K)),
      // A_K = 2 / ((gamma + 1) rho_K), B_K = (gamma - 1)/(gamma + 1) p_K.
      const double A = 2.0 / ((gamma_ + 1.0) * w.rho);
      const double B = (gamma_ - 1.0) / (gamma_ + 1.0) * w.p;
      const double root = std::sqrt(A / (p + B));
      return {(p - w.p) * root, root * (1.0 - 0.5 * (p - w.p) / (p + B))};
    }
    // Rarefaction branch, from isentropy and the generalised Riemann invariant across the fan:
    // f_K = 2 a_K/(gamma - 1) [(p/p_K)^((gamma - 1)/(2 gamma)) - 1],
    // f_K' = (p/p_K)^(-(gamma + 1)/(2 gamma)) / (rho_K a_K).
    const double ratio = p / w.p;
    return {2.0 * a / (gamma_ - 1.0) * (std::pow(ratio, (gamma_ - 1.0) / (2.0 * gamma_)) - 1.0),
            std::pow(ratio, -(gamma_ + 1.0) / (2.0 * gamma_)) / (w.rho * a)};
  }

  Branch pressure_function(double p) const {
    const Branch fl = wave_function(p, left_, a_left_);
    const Branch fr = wave_function(p, right_, a_right_);
    return {fl.f + fr.f + (right_.u - left_.u), fl.df + fr.df};
  }

  // Newton-Raphson for the root of f (Toro (2009) section 4.3), started from the two-rarefaction
  // guess. That guess solves f = 0 exactly with both f_K on their rarefaction branches, so it is
  // exact when both waves are rarefactions (Toro's test 2 takes no correction) and is a good
  // start otherwise. f is increasing and concave, so from above the root a Newton step lands at
  // or below it (for strong shocks possibly at p <= 0), and from below the iterates rise
  // monotonically to it. For 1 < gamma <= 5/3 the guess is found to be at or above p* (to
  // round-off), but for larger gamma it can start below, with no upper bound known yet. A bracket
  // [lo, hi] with f(lo) < 0 <= f(hi), hi = infinity until some f(p) >= 0, replaces any step that
  // leaves it by bisection (by doubling while hi is open), so every iterate is positive. Stops
  // when the Newton correction is below 1e-14 of p (the last correction is applied), when the
  // bracket is that narrow, or when f(p) is exactly zero.
  void solve_star_pressure() {
    constexpr double kRelativeTolerance = 1e-14;
    constexpr int kMaxIterations = 200;
    const double z = (gamma_ - 1.0) / (2.0 * gamma_);
    // Two-rarefaction guess: positive because the no-vacuum check made the numerator positive.
    const double numerator = a_left_ + a_right_ - 0.5 * (gamma_ - 1.0) * (right_.u - left_.u);
    const double denominator = a_left_ / std::pow(left_.p, z) + a_right_ / std::pow(right_.p, z);
    double p = std::pow(numerator / denominator, 1.0 / z);
    if (!(p > 0.0) || !std::isfinite(p)) p = 0.5 * (left_.p + right_.p);

    // f(0) < 0 without vacuum, so lo = 0 starts a valid bracket.
    double lo = 0.0;
    double hi = std::numeric_limits<double>::infinity();
    Branch f = pressure_function(p);
    for (iterations_ = 1; iterations_ <= kMaxIterations; ++iterations_) {
      if (f.f == 0.0) break;
      (f.f < 0.0 ? lo : hi) = p;
      const double newton = p - f.f / f.df;
      // Converged when the Newton correction is negligible. Tested before the bracket, because
      // at the root p itself is an end of the bracket and a step of a rounding error may touch
      // or cross it; rejecting that step would restart the search by bisection.
      if (newton > 0.0 && std::abs(newton - p) < kRelativeTolerance * p) {
        p_star_ = newton;
        return;
      }
      // Rounding in f bounds how close to the root its sign is meaningful; once the bracket is
      // that narrow (as for gamma -> 1 with large 2 a_K/(gamma - 1) terms) the root is known.
      if (std::isfinite(hi) && hi - lo <= kRelativeTolerance * hi) {
        p_star_ = p;
        return;
      }
      p = newton > lo && newton < hi ? newton : (std::isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * p);
      f = pressure_function(p);
    }
    if (f.f != 0.0) {
      throw std::runtime_error("RiemannSolution: Newton iteration for p* did not converge");
    }
    p_star_ = p;
  }

  // Q_K of the shock speed (see left_shock_speed()): the shock's Mach number relative to the gas
  // ahead of it, |u_K - S_K| / a_K.
  double shock_mach(const GasState& w) const {
    return std::sqrt((gamma_ + 1.0) / (2.0 * gamma_) * p_star_ / w.p +
                     (gamma_ - 1.0) / (2.0 * gamma_));
  }

  // Density of the star state next to W_K (Toro (2009) section 4.4): behind a shock from the
  // Rankine-Hugoniot conditions (the shock adiabat),
  //   rho*K = rho_K (p*/p_K + mu) / (mu p*/p_K + 1),  mu = (gamma - 1)/(gamma + 1),
  // behind a rarefaction from isentropy, rho*K = rho_K (p*/p_K)^(1/gamma).
  double star_density(const GasState& w) const {
    const double ratio = p_star_ / w.p;
    if (p_star_ > w.p) {
      const double mu = (gamma_ - 1.0) / (gamma_ + 1.0);
      return w.rho * (ratio + mu) / (mu * ratio + 1.0);
    }
    return w.rho * std::pow(ratio, 1.0 / gamma_);
  }

  // Sound speed in the star state behind a rarefaction, a*K = a_K (p*/p_K)^((gamma-1)/(2 gamma)),
  // from isentropy; it places the fan's tail at u* -/+ a*K.
  double star_sound_speed(const GasState& w, double a) const {
    return a * std::pow(p_star_ / w.p, (gamma_ - 1.0) / (2.0 * gamma_));
  }

  // Inside a left fan, on the characteristic dx/dt = u - a = s (Toro (2009) section 4.4): the
  // Riemann invariant u + 2a/(gamma - 1) is that of W_L, which with u - a = s gives
  //   u = 2/(gamma + 1) (a_L + (gamma - 1)/2 u_L + s),   a = u - s,
  // and isentropy gives rho = rho_L (a/a_L)^(2/(gamma - 1)), p = p_L (a/a_L)^(2 gamma/(gamma - 1)).
  // c below is a/a_L, written with s.
  GasState inside_left_fan(double s) const {
    const double c =
        2.0 / (gamma_ + 1.0) + (gamma_ - 1.0) / ((gamma_ + 1.0) * a_left_) * (left_.u - s);
    return {left_.rho * std::pow(c, 2.0 / (gamma_ - 1.0)),
            2.0 / (gamma_ + 1.0) * (a_left_ + 0.5 * (gamma_ - 1.0) * left_.u + s),
            left_.p * std::pow(c, 2.0 * gamma_ / (gamma_ - 1.0))};
  }

  // Mirror image for a right fan, characteristic u + a = s, invariant u - 2a/(gamma - 1):
  //   u = 2/(gamma + 1) (-a_R + (gamma - 1)/2 u_R + s),   a = s - u,   c = a/a_R.
  GasState inside_right_fan(double s) const {
    const double c =
        2.0 / (gamma_ + 1.0) - (gamma_ - 1.0) / ((gamma_ + 1.0) * a_right_) * (right_.u - s);
    return {right_.rho * std::pow(c, 2.0 / (gamma_ - 1.0)),
            2.0 / (gamma_ + 1.0) * (-a_right_ + 0.5 * (gamma_ - 1.0) * right_.u + s),
            right_.p * std::pow(c, 2.0 * gamma_ / (gamma_ - 1.0))};
  }

  GasState left_;
  GasState right_;
  double gamma_;
  double a_left_ = 0.0;
  double a_right_ = 0.0;
  double p_star_ = 0.0;
  double u_star_ = 0.0;
  double rho_star_left_ = 0.0;
  double rho_star_right_ = 0.0;
  int iterations_ = 0;
};

}  // namespace flume
