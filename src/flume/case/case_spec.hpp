// A case, read, validated and resolved: every value the run needs, in SI units, with the
// dimension still a run-time number (vectors have `dimension` entries). The command line only
// builds a CaseSpec; the library builds the simulation from it.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "flume/validation/curve_compare.hpp"

namespace flume {

struct FluidBlock {
  std::vector<double> min, max;  // m
  std::vector<double> velocity;  // m/s, at the block's centre
  // d v / d x, row-major D x D, 1/s: v = velocity + G (x - centre) (the elliptical drop's
  // (-A x, A y) of BL 5.2)
  std::vector<double> velocity_gradient;
  bool hydrostatic = true;         // initial density in hydrostatic equilibrium under gravity
  double density = 0.0;            // kg/m^3, uniform; 0 = the fluid's (hydrostatic or rho0)
  double internal_energy = 0.0;    // J/kg, an ideal gas's e
  double spacing = 0.0;            // m, the block's own lattice spacing; 0 = particles.spacing
  std::string shape = "box";       // "box" or "ellipsoid" (inscribed in min, max)
  std::string layout = "lattice";  // "lattice" (spacing dx) or "random" (count, seed)
  long count = 0;                  // particles of a random layout
  long seed = 1;                   // its random seed (std::mt19937_64)
  double min_distance = 0.0;       // spacings: no two random particles closer (0 = Poisson)
  // A free surface that is not flat (2D, the box's top): y = max_y + B exp(-k d), W (6.21), with
  // d the distance along x from the side surface_from (0 = x_min, 1 = x_max): the mound that
  // collapses into a solitary wave (W 6.4.1). B = 0: a flat top.
  double surface_amplitude = 0.0;  // B, m
  double surface_decay = 0.0;      // k, 1/m
  int surface_from = 0;            // 0: the mound at x_min; 1: at x_max
  // Or a KdV solitary wave already formed (2D, the box's top): y = max_y + A sech^2((x - x0) /
  // lambda), W (6.15)-(6.17) on the still depth H = max_y - min_y, travelling toward x_max (or
  // x_min) with the water's velocity of theory/solitary_wave.hpp (kdv_velocity) added to the
  // block's. A = 0: none.
  double solitary_amplitude = 0.0;  // A, m
  double solitary_centre = 0.0;     // x0, m
  int solitary_towards = 1;         // +1: toward x_max; -1: toward x_min
  // "none", or "velocity_field": the incompressible pressure of the block's straining flow
  // (case/affine_flow_pressure.hpp), the density from it through the EOS.
  std::string initial_pressure = "none";
};

// A wall side moving along its normal (boundaries/wall_motion.hpp).
struct MovingWall {
  int axis = 0;
  int side = 0;            // 0 lower, 1 upper
  double velocity = 0.0;   // m/s
  double amplitude = 0.0;  // m
  double period = 0.0;     // s
};

// A wall of repulsive boundary particles (boundaries/repulsive_walls.hpp, 2D): a plane slope, or
// the piston-flap paddle W (6.9) when stroke is not 0.
struct RepulsiveWallSpec {
  std::vector<double> from, to;        // m, the fluid on the left walking from `from` to `to`
  std::string force = "monaghan_kos";  // W (6.10)-(6.12), or "lennard_jones" W (6.7)
  double spacing = 0.0;                // m, the boundary particles' spacing (resolved)
  double strength = 0.0;               // D of W (6.7), m^2/s^2 (resolved)
  double cutoff = 0.0;                 // r0 of W (6.7), m (resolved)
  double power_repulsive = 12.0, power_attractive = 4.0;  // p1, p2 of W (6.7)
  double put_back_distance = 0.0;                         // Delta z of W (6.8), m (resolved)
  double clearance = 0.0;       // m: no fluid particle starts nearer (resolved: the force's reach)
  double reach = 0.0;           // m: Monaghan-Kos's q = y / reach (resolved; 0 in the file: 2h)
  double stroke = 0.0;          // A of W (6.9), m; 0: no motion
  double frequency = 0.0;       // f, Hz
  double phase = 0.0;           // rad
  double hinge_depth = 0.1344;  // alpha0, m
  double reference_height = 0.15;  // y0, m
};

// A probe curve compared with a reference data set (validate).
struct CurveCheck {
  std::string probe;                // probes.csv column
  std::string label;                // for the report
  std::filesystem::path reference;  // CSV, resolved against the case file's folder
  std::string theory;               // or a solution flume computes: "elliptical_drop"
  std::string reference_x;          // its column of dimensionless time
  std::string reference_y;          // its column of the dimensionless probe value
  std::string source;               // where the reference comes from
  double value_scale = 1.0;         // probe value (m) divided by this gives the reference's y
  bool absolute = false;            // error in the reference's units instead of relative
  double tolerance = 0.1;           // max error allowed over the compared points
  double quick_tolerance = 0.1;
  double mean_tolerance = 0.0;  // bound on the mean error over the points; 0 = not checked
  double quick_mean_tolerance = 0.0;
  bool gated = true;  // false: reported beside the others, never fails validation
  // What is compared (curve_compare.hpp) over the reference's x in [window_from, window_to].
  CurveStatistic statistic = CurveStatistic::pointwise;
  double window_from = 0.0;
  double window_to = 0.0;  // 0 = to the reference's last point
  // reference = "self": the same statistic of the same probe over this earlier window (a
  // speed or height that must not change between passes of a periodic tank).
  double reference_from = 0.0;
  double reference_to = 0.0;
  double at = 0.0;  // line_at's x (s): e.g. when two waves met, for the phase shift
  // reference = "run:LABEL" (theory "run"): the same statistic, over the same window, of
  // column reference_probe of the companion run LABEL (validation.companions): a wave's height
  // after a collision against the same wave's, alone in the same tank, at the same times.
  std::string companion;
  std::string reference_probe;  // the companion's probes.csv column; "" = probe
};

// A profile field compared with a reference solution at the end time (validate): the relative
// L1 error sum |f - f_exact| / sum |f_exact| over the particles of profile.csv.
struct ProfileCheck {
  std::string field;               // "rho", "p" or "u"
  std::string theory = "riemann";  // the exact Riemann solution of the first two blocks
  double tolerance = 0.1;
  double quick_tolerance = 0.1;
  bool gated = true;
};

struct CaseSpec {
  std::filesystem::path file;  // the case file read
  std::string resolved_toml;   // the fully resolved case file (every default written out)

  // [case]
  std::string name;
  std::string description;
  int dimension = 2;
  double end_time = 1.0;  // s
  double dt = 0.0;        // s; 0 = CFL rule

  // [particles]
  double spacing = 0.0;         // m
  std::string mass = "volume";  // or "summation" (case/summation_masses.hpp)

  // [scheme]
  std::string preset;
  std::string kernel;
  std::string density;                     // resolved row
  std::string force;                       // resolved row
  std::string correction;                  // resolved row
  std::string smoothing_length = "fixed";  // or "evolving", W (2.22)
  std::string integrator = "leapfrog";     // or "runge_kutta", "modified_runge_kutta"
  std::string time_step = "bl63";          // or "w388": W (3.88)-(3.90)
  std::string viscous_term = "bl24";       // or "w511" (W (5.11)), "w57" (Morris)
  std::string turbulence = "none";         // resolved row: or "smagorinsky" (LES-SPH)
  double smagorinsky_cs = 0.12;            // C_s of W (5.19)
  double yoshizawa_ci = 0.0066;            // C_I of W (5.32)
  double filter_width = 0.0;               // m, Delta of W (5.19); 0 = the spacing
  double xsph = 0.0;                       // XSPH's eps, W (6.6); 0 = off
  double h_over_dx = 1.3;
  double cfl = 0.3;
  double alpha = 0.0;
  double beta = 0.0;

  // [fluid] and [eos]
  std::string eos = "tait";     // or "ideal_gas"
  double rho0 = 1000.0;         // kg/m^3
  double mu = 0.0;              // Pa s
  std::vector<double> gravity;  // m/s^2
  double gamma = 7.0;
  double bulk_modulus = 0.0;  // Pa, resolved
  double sound_speed = 0.0;   // m/s, resolved

  // [domain] and [boundaries]
  std::vector<double> domain_min, domain_max;  // m
  // per axis lower, upper: "free_slip" | "no_slip" | "open" | "periodic" (both sides of an axis)
  std::vector<std::string> walls;
  double periodic_from = 0.0;  // s: periodic sides are free-slip walls before this time (W 6.4.2)
  // "mirrored" (W 6.1: ghosts copy p and rho) | "hydrostatic" (p plus rho g . (x_ghost - x))
  std::string ghost_pressure = "mirrored";
  std::vector<FluidBlock> blocks;
  std::vector<MovingWall> moving_walls;
  std::vector<RepulsiveWallSpec> repulsive_walls;

  // [output]
  double output_interval = 0.01;    // s, diagnostics and probes
  double snapshot_interval = 0.05;  // s; 0 = no snapshots
  int shepard_every = 0;            // steps between density filters, W (6.3); 0 = off
  // The filter's average: "shepard" (W (6.3)) | "first_order" (BL (47)-(52)'s kernel)
  std::string density_filter = "shepard";
  bool profile = false;       // profile.csv at the end time
  int profile_axis = 1;       // the particles near the line x[axis] = profile_at
  double profile_at = 0.0;    // m
  double profile_band = 2.0;  // spacings

  // [probes]
  bool surge_front = false;
  bool column_height = false;
  bool semi_axes = false;      // semi_axis_x, semi_axis_y from the cloud's second moments (2D)
  bool bore = false;           // bore_front, bore_height (probes/bore.hpp)
  double floor_layer = 2.0;    // spacings
  double wall_band = 2.0;      // spacings
  double detach_gap = 3.0;     // spacings
  bool waves = false;          // crest_x, crest_amplitude, gauge_1... (probes/wave_probes.hpp, 2D)
  std::vector<double> gauges;  // m along x: wave gauges
  double second_crest = 0.0;   // m: crest2_x, crest2_amplitude at least this far away; 0 = off
  bool crest_profile = false;  // crest_width, crest_shape (probes/crest_profile.hpp)
  double still_depth = 0.0;    // m, H: resolved (the first fluid block's height unless given)
  bool still_water = false;    // bed_pressure, water_level
  bool density_deviation = false;   // density_deviation: max |rho - rho0| / rho0
  bool centre_of_mass = false;      // centre_x, centre_y(, centre_z): the water's centre of mass
  bool breaking = false;            // overturn, broken_at (probes/breaking.hpp, 2D)
  double breaking_threshold = 4.0;  // spacings: an air gap under water this tall is breaking
  std::vector<double> bed_span;     // m, [x_lo, x_hi] of bed_pressure; empty: middle 80 %
  double beach_slope = 0.0;         // s: incident_amplitude, grilli_s0, grilli_breaks; 0 = off
  double beach_toe = 0.0;           // m

  // [checkpoint] (run/checkpoint.hpp)
  long checkpoint_every_steps = 0;      // steps between checkpoints; 0 = not by steps
  double checkpoint_every_seconds = 0;  // wall-clock s between checkpoints; 0 = not by time
  int checkpoint_keep = 2;              // the newest checkpoints kept

  // [checks] (sim/simulation.hpp): failure detection in every step
  double density_band_lo = 0.2;  // times the lowest starting density
  double density_band_hi = 5.0;  // times the highest starting density
  double min_dt_ratio = 1e-4;    // the smallest step allowed, times the first step

  // [validation]
  std::vector<std::string> quick;     // KEY=VALUE overrides of the reduced-resolution run
  double time_scale = 1.0;            // s: reference time = t / time_scale
  std::vector<std::string> notes;     // the papers' numbers, set beside flume's in the report
  std::vector<std::string> variants;  // KEY=VALUE: other configurations run and reported beside
  bool quick_variants = true;         // whether validate --quick runs the variants too
  // [LABEL:] KEY=VALUE; ...: companion runs, each configuration's own case with these overrides
  // on top, whose probes are references of curves ("run:LABEL"; validation/validate.cpp).
  std::vector<std::string> companions;
  std::vector<double> pictures;  // s: particle pictures of every configuration at these times
  // s: the surface near the highest crest against KdV's A sech^2 of its height, every
  // configuration in one plot (scripts/plot_crest_profile.py; 2D wave tanks)
  std::vector<double> crest_pictures;
  std::string picture_field;                   // the snapshot field that colours them
  std::vector<std::string> diagnostics_plots;  // diagnostics.csv columns plotted for every run
  std::vector<CurveCheck> curves;
  std::vector<ProfileCheck> profiles;
  // A convergence study (validate): the case as written, with convergence_sets on top, run at
  // each spacing, coarse to fine; curve convergence_curve's largest error must fall at each step.
  std::vector<double> convergence_spacings;        // m; empty = no study
  std::vector<double> quick_convergence_spacings;  // m, for validate --quick; empty = none
  std::vector<std::string> convergence_sets;       // KEY=VALUE overrides of every run of the study
  std::size_t convergence_curve = 0;               // index into curves
};

// |g|, m/s^2: the length of the case's gravity vector.
inline double gravity_magnitude(const CaseSpec& spec) {
  double g2 = 0.0;
  for (double x : spec.gravity)
    g2 += x * x;
  return std::sqrt(g2);
}

// H, m: the tallest body of water, the largest height of a fluid block (with its mound, W (6.21)).
inline double tallest_water(const CaseSpec& spec) {
  double h = 0.0;
  for (const auto& b : spec.blocks)
    h = std::max(h, b.max.back() + b.surface_amplitude + b.solitary_amplitude - b.min.back());
  return h;
}

}  // namespace flume
