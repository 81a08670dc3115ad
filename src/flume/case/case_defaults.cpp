// The documented default of every case-file key. This text is the schema: a key that is not here
// is unknown, and a value must have the type shown. Vectors have one entry per dimension.
#include <fmt/format.h>

#include "flume/case/case_reader.hpp"

namespace flume {

namespace {
std::string defaults_for(int d) {
  const std::string zero = d == 3 ? "[0.0, 0.0, 0.0]" : "[0.0, 0.0]";
  const std::string one = d == 3 ? "[1.0, 1.0, 1.0]" : "[1.0, 1.0]";
  const std::string gravity = d == 3 ? "[0.0, 0.0, -9.81]" : "[0.0, -9.81]";
  const std::string z_walls = d == 3 ? "z_min = \"free_slip\"\nz_max = \"free_slip\"\n" : "";
  return fmt::format(R"toml(# flume case file: every key, its default and its unit.
[case]
name = ""              # required: letters, digits, '_' and '-'; also the output folder name
description = ""       # one line, shown by `flume cases`
dimension = 2          # 2 or 3; the last axis is vertical
end_time = 1.0         # s
dt = 0.0               # fixed time step, s; 0 = the CFL rule of BL (63)

[particles]
spacing = 0.001        # initial particle spacing dx, m (particles on a square lattice)
mass = "volume"        # volume: m = rho times the particle's volume (dx^D on a lattice) |
                       # summation: m_a = rho_a / sum_b W_ab(h_a), so that the summation density
                       # BL (1) starts at each block's density (no tension at a free surface;
                       # open boundaries only: the sum has no wall ghosts)

[scheme]
preset = "continuity"  # standard | continuity | inconsistent | csph | sph-euler | wsph | rsph |
                       # les-sph (spec/methods.md)
kernel = "cubic_spline"  # cubic_spline | quintic_spline | gaussian | wendland_c2
h_over_dx = 1.3        # smoothing length h = h_over_dx * spacing
density = ""           # override of the preset's row: summation (BL (1)) | continuity (BL (4)) |
                       # w350 (W (3.50)) | w379 (W (3.79), sign corrected)
force = ""             # override of the preset's row: bl7 (BL (7)) | bl20 (BL (20)) | bl59 (CSPH) |
                       # w351 (W (3.51)-(3.52)) | w380 (W (3.80)-(3.81)); the W forces carry
                       # their energy equations and pair with their own density row
correction = ""        # override of the preset's row (BL section 4): none | shepard (BL (53)) |
                       # first_order (BL (47)-(52)) with a summation density (the density's
                       # kernel); none | gradient (BL (42)-(45)) | shepard (BL (53), (57)) |
                       # mixed (CSPH, BL (54)-(58)) with a continuity density (its gradient);
                       # none | renormalized (R-SPH, W (4.8)-(4.16)) with w379 + w380
integrator = "leapfrog"  # leapfrog (BL (61)-(62)) | runge_kutta (W (3.85)-(3.87)) |
                       # modified_runge_kutta (W (3.92), keeps linear momentum)
smoothing_length = "fixed"  # fixed | evolving (W (2.22) with the scheme's own d rho/dt; an
                       # evolved density only)
time_step = "bl63"     # bl63: BL (63) with the body-force and viscous limits | w388: W (3.88)-
                       # (3.90), the local sound speed and the pairs' max |h u_ij.x_ij|/|x_ij|^2,
                       # times cfl (W: 0.3); both with the viscous limit (time_step.hpp)
viscous_term = "bl24"  # how fluid.viscosity enters: bl24 (BL (22)-(25)) | w511 (W (5.11), grad u
                       # from W (5.5)) | w57 (Morris, W (5.7)); only bl24 with a corrected
                       # continuity density (csph, gradient, shepard: BL (59) holds its stress)
turbulence = ""        # override of the preset's row: none | smagorinsky (LES-SPH, W (5.31)-
                       # (5.34); a liquid; not with a corrected continuity density)
smagorinsky_cs = 0.12  # C_s of W (5.19), -
yoshizawa_ci = 0.0066  # C_I of W (5.32), -
filter_width = 0.0     # LES filter width Delta, m; 0 = particles.spacing (W)
xsph = 0.0             # XSPH eps, W (6.6), 0 <= eps <= 1 (0.5 usual); 0 = off
cfl = 0.3              # Courant number C_FL of BL (63), or W (3.90)'s factor
alpha = 0.0            # artificial viscosity alpha, W (3.18); 0 = off
beta = 0.0             # artificial viscosity beta, W (3.18)
shepard_every = 0      # steps between density filters W (6.3) (W: 40); 0 = off;
                       # continuity density only
density_filter = "shepard"  # the filter's average: shepard (W (6.3)) | first_order (W (6.3)
                       # with BL (47)-(52)'s corrected kernel: keeps a linear density, so a
                       # hydrostatic column's surface, as it is)

[fluid]
density = 1000.0       # reference density rho0, kg/m^3
viscosity = 0.0        # dynamic viscosity mu, Pa s (BL (22)-(25)); 0 = inviscid
gravity = {gravity}    # m/s^2

[eos]
kind = "tait"          # tait: BL (60), gamma, p_atm = 0 | ideal_gas: p = (gamma - 1) rho e, e
                       # from the fluid blocks (W's schemes only: they carry its energy)
gamma = 7.0            # Tait exponent, or the gas's ratio of specific heats
bulk_modulus = 0.0     # kappa, Pa; 0 = from sound_speed
sound_speed = 0.0      # c0, m/s; 0 = speed_ratio * max_flow_speed (BL (64))
speed_ratio = 10.0     # m of BL (64): c0 = m u_max
max_flow_speed = 0.0   # u_max, m/s; 0 = sqrt(2 g H), H the tallest fluid block (BL (66))

[domain]
min = {zero}           # box corner, m
max = {one}            # box corner, m

[boundaries]           # each side: free_slip | no_slip (mirror ghosts, W 6.1) | open |
                       # periodic (both sides of a horizontal axis: ghosts are the other end's
                       # particles shifted by the domain's length, and a particle that leaves
                       # re-enters at the other end, W 6.1)
x_min = "free_slip"
x_max = "free_slip"
y_min = "free_slip"
y_max = "free_slip"
{z_walls}periodic_from = 0.0    # s: periodic sides are free-slip walls before this time (W 6.4.2
                       # forms the wave in a closed tank and makes it periodic at t = 4 s)
ghost_pressure = "mirrored"  # mirrored (W 6.1: a mirror ghost copies p and rho) | hydrostatic
                       # (a Tait liquid's: the ghost's p adds rho g . (x_ghost - x), its rho
                       # is the Tait density of that p, so the pressure runs on straight
                       # through a floor instead of folding back)

[output]
interval = 0.01        # s between rows of diagnostics.csv and probes.csv
snapshot_interval = 0.05  # s between ParaView snapshots; 0 = none
profile = false        # profile.csv at the end: x,y(,z),rho,p,u,v(,w),e of the particles within
                       # profile_band spacings of the line x[profile_axis] = profile_at, by x
profile_axis = "y"     # x | y | z
profile_at = 0.0       # m
profile_band = 2.0     # spacings

[probes]
surge_front = false    # distance from domain.min along x to the leading particle on the floor
semi_axes = false      # semi_axis_x, semi_axis_y (m): 2 sqrt(<(x - <x>)^2>) mass-weighted, the
                       # semi-axes of a uniform ellipse with those second moments (2D)
column_height = false  # height of the water at the x_min wall
bore = false           # bore_front (m from the x_min wall) and bore_height (m above the floor)
                       # of a bore running away from the x_min wall (BL 5.4; probes/bore.hpp)
floor_layer = 2.0      # surge front: particles within this many spacings of the floor count
wall_band = 2.0        # column height: particles within this many spacings of the wall count
detach_gap = 3.0       # spacings: particles farther than this from the main body of water are
                       # spray, counted by neither probe
waves = false          # 2D wave tank (probes/wave_probes.hpp): crest_x (m, where the depth
                       # of water, from the particles' masses, is highest; unwrapped in a
                       # periodic tank), crest_amplitude (m, that depth minus still_depth),
                       # crest_centre_x (m, the centroid of the crest's upper half: steadier
                       # than crest_x where the top is flat)
gauges = []            # m along x: wave gauges gauge_1, gauge_2, ... (m, the depth there minus
                       # still_depth); needs waves = true
second_crest = 0.0     # m: also crest2_x, crest2_amplitude, the highest other crest at least
                       # this far from the highest (two waves in one tank); 0 = off
crest_profile = false  # crest_width (m: the least-squares lambda of A sech^2((x - crest_x) /
                       # lambda) against the surface within 3 KdV widths of the crest) and
                       # crest_shape (the RMS deviation there from KdV's profile of amplitude
                       # crest_amplitude, W (6.15), over it; probes/crest_profile.hpp) and
                       # crest_fit_amplitude (m: the amplitude of the least-squares
                       # A' sech^2((x - crest_x) / lambda') there, A' and lambda' free: steadier
                       # than crest_amplitude; with second_crest, crest2_fit_amplitude too);
                       # needs waves = true
still_depth = 0.0      # m, H of the tank; 0 = the first fluid block's top above domain.min
still_water = false    # bed_pressure (Pa: the four bottom rows' p + rho0 g y, middle 80 % of
                       # the width) and water_level (m: twice the particles' mean height)
bed_span = []          # m, [x_lo, x_hi]: where bed_pressure is read instead (a flat bed
                       # before a beach); [] = the middle 80 % of the tank
density_deviation = false  # density_deviation: max |rho - rho0| / rho0 over the particles
centre_of_mass = false # centre_x, centre_y (, centre_z): the water's centre of mass, m
breaking = false       # 2D wave tank (probes/breaking.hpp): overturn (m, the tallest air gap under
                       # water in any column two spacings wide of the main body) and broken_at
                       # (s, the first time it exceeded breaking_threshold spacings; 0 before)
                       # and broken_x (m, the column where it did; 0 before)
breaking_threshold = 4.0  # spacings
beach_slope = 0.0      # s of a plane beach (rise / run; 0 = none): with waves = true, the
                       # columns incident_amplitude (m, the crest amplitude at the last reading
                       # before the crest reached beach_toe), grilli_s0 (W (6.20) for it) and
                       # grilli_breaks (1 if A / H > 16.9 s^2, W (6.19), else 0)
beach_toe = 0.0        # m along x: where the beach starts

[checkpoint]           # HDF5 checkpoints in checkpoints/ of the run directory (flume resume)
every_steps = 0        # steps between checkpoints; 0 = not by steps
every_seconds = 0.0    # wall-clock seconds between checkpoints; 0 = not by time
keep = 2               # how many of the newest checkpoints are kept (>= 1)

[checks]               # failure detection after every step: a failed check ends the run (exit 1)
density_band = [0.2, 5.0]  # a density must stay within [lo x the lowest, hi x the highest]
                       # starting density (0 < lo < 1 < hi)
min_dt_ratio = 1e-4    # the step may not collapse below this fraction of the first step
                       # (0 < ratio < 1)

[validation]
quick = []             # "KEY=VALUE" overrides of the reduced-resolution run (validate --quick)
time_scale = 1.0       # s; the references' time is t / time_scale
notes = []             # the papers' own numbers, quoted in the report
variants = []          # "KEY=VALUE": other configurations run and reported beside the case
quick_variants = true  # whether validate --quick runs the variants too (false: the case alone,
                       # for a case whose runs are long)
companions = []        # "LABEL: KEY=VALUE; ...": companion runs of every configuration run (the
                       # configuration's overrides, then these), whose probes are the references
                       # of curves with reference = "run:LABEL" (a wave alone in the same tank)
pictures = []          # s: particle pictures (PNG) of every configuration near these times (later than end_time: left out)
picture_field = "velocity_x"  # what colours them: a snapshot field, NAME_x/_y/_z a component
crest_pictures = []    # s: the surface near the highest crest of every configuration against KdV's
                       # A sech^2((x - x_c) / lambda) of its height, the snapshot nearest each time
                       # (2D, probes.waves; later than end_time: left out)
diagnostics_plots = []  # diagnostics.csv (or probes.csv) columns plotted against time for every
                        # configuration
convergence_spacings = []  # m, coarse to fine: a convergence study, the case as written run at
                           # each particles.spacing (every block on the lattice, without a spacing
                           # of its own); the largest error of curve convergence_curve must fall
                           # at each step (validate; the quick overrides do not apply)
quick_convergence_spacings = []  # m: the study of validate --quick (empty: none)
convergence_sets = []  # "KEY=VALUE" overrides of every run of the study (for example a stiffer
                       # fluid and a shorter step, so that the spatial error is the one seen)
convergence_curve = 0  # which [[validation.curves]] entry the study follows (0 = the first)

# [[fluid_blocks]]: at least one; each a body of fluid:
#   min = {zero}, max = {one} (m), velocity = {zero} (m/s, at the centre), hydrostatic = true,
#   density = 0.0 (kg/m^3; 0 = fluid.density; a given density is uniform, not hydrostatic),
#   internal_energy = 0.0 (J/kg, the specific internal energy e of an ideal gas; required > 0
#   with eos.kind = "ideal_gas"), spacing = 0.0 (m: the block's own lattice spacing, its
#   smoothing length h_over_dx times it; 0 = particles.spacing),
#   velocity_gradient = D x D zeros, row-major (1/s): v = velocity + G (x - centre),
#   shape = "box" (or "ellipsoid": the ellipse or ellipsoid inscribed in min, max),
#   layout = "lattice" (particles at the cell centres of spacing dx inside the shape, mass
#   rho dx^D) or "random" (count particles uniformly inside the shape from seed, equal masses
#   rho volume / count; spacing then sets only h), count = 0, seed = 1, min_distance = 0.0
#   (spacings, at most 1: a random candidate closer than that to a placed particle is drawn
#   again; 0 = independent uniform positions). A random body is moved as a whole so that its
#   centre of mass is the shape's centre. surface_amplitude = 0.0 (m, B), surface_decay = 0.0
#   (1/m, k), surface_from = "x_min" (or "x_max"): a 2D lattice box whose top is
#   y = max_y + B exp(-k d), d the distance from that side (W (6.21): the mound that collapses
#   into a solitary wave); with hydrostatic = true each column starts hydrostatic under its own
#   surface. solitary_amplitude = 0.0 (m, A), solitary_centre = 0.0 (m, x0), solitary_towards =
#   "x_max" (or "x_min"): a 2D lattice box whose top is a KdV solitary wave already formed,
#   y = max_y + A sech^2((x - x0) / lambda), lambda = sqrt(4 H^3 / (3 A)) on the still depth
#   H = max_y - min_y (W (6.15)-(6.17), A below 0.78 H), travelling toward that side: each
#   particle gets the depth-uniform u = V eta / (H + eta) and w = -(y - min_y) du/dx (both
#   negated toward x_min), V = sqrt(g H)(1 + A / (2 H)) (theory/solitary_wave.hpp), on top
#   of the block's velocity, and with hydrostatic = true each column starts hydrostatic under
#   its own surface. Not with surface_amplitude. initial_pressure = "none" (or
#   "velocity_field": an ellipsoid of liquid whose velocity_gradient is diagonal with zero
#   trace starts at the pressure of that incompressible straining flow, zero on its surface,
#   its density from the EOS: BL 5.2's drop without the acoustic start-up;
#   case/affine_flow_pressure.hpp).
# [[moving_walls]]: a wall side that moves along its normal with a prescribed motion (the bore's
#   push wall, BL 5.4; a piston wave-maker): side = "x_max" (any side that is a wall),
#   velocity = 0.0 (m/s, along the axis), amplitude = 0.0 (m), period = 0.0 (s): the wall stands
#   at its domain position + velocity t + amplitude sin(2 pi t / period). Its ghosts mirror the
#   fluid's velocity relative to the wall.
# [[repulsive_walls]]: a wall of repulsive boundary particles (W 6.2, 2D): a plane slope at any
#   angle, or a paddle. from = [x, y], to = [x, y] (m): a straight wall with the fluid on its
#   left as one walks from `from` to `to` (a beach rising to the right runs from its toe up);
#   clearance = 0.0 (m: no fluid particle starts behind it or nearer than this; 0 = the force's
#   reach, `reach` for monaghan_kos and cutoff for lennard_jones, where water at rest settles).
#   force = "monaghan_kos" (W (6.10)-(6.12), q = y / 2h, A = 0.01 c^2 / h: a smooth wall;
#   reach = 0.0, spacings: q = y / reach instead, 0 = 2h, more than put_back_distance (the force
#   is taken no nearer than that distance); water at rest sits up to the reach
#   off the wall, so a reach of one spacing keeps a beach's water near the bed's, whose mirror
#   holds it half a spacing off) or
#   "lennard_jones" (W (6.7): strength = D, m^2/s^2, 0 = 5 g H with H the tallest fluid
#   block; cutoff = r0, m, 0 = spacing; powers = [p1, p2], p1 > p2: a rugged wall);
#   spacing = 0.0 (m, the boundary particles' spacing; 0 = particles.spacing);
#   put_back_distance = 0.5 (spacings: a particle that crosses the wall is put back this far in
#   front of it, W (6.8), its normal velocity relative to the wall mirrored).
#   The piston-flap paddle W (6.9): stroke = 0.0 (A, m; 0 = a fixed wall), frequency = 0.0
#   (f, Hz), phase = 0.0 (rad: A(t) = A cos(2 pi f t + phase); W's is 0, -pi/2 starts at rest),
#   hinge_depth = 0.1344 (alpha0, m), reference_height = 0.15 (y0, m): a point of the wall at
#   height y above `from` moves along x by (1/2) ((y + alpha0) / (y0 + alpha0)) A(t).
# [[validation.curves]]: a probe compared with a reference curve:
#   probe = "surge_front", label = "", reference = "path.csv" (relative to this file),
#   reference_x = "T", reference_y = "Z", source = "", value_scale = 1.0 (m),
#   error = "relative" (or "absolute": in the reference's units), tolerance = 0.1,
#   quick_tolerance = 0.1 (the largest error allowed over the compared points),
#   mean_tolerance = 0.0, quick_mean_tolerance = 0.0 (the mean error allowed; 0 = not checked),
#   reference = "theory:elliptical_drop": the exact solution of BL 5.2 computed by flume, with
#   columns t (s), a and b (m), from the first fluid block (radius, velocity gradient),
#   reference = "theory:bore": BL (67)-(68) for the first fluid block's depth and speed, with
#   columns t (s), front (m, v_s t from the x_min wall) and height (m),
#   gated = true (false: the curve is reported beside the others but cannot fail validation),
#   statistic = "pointwise" (every reference point), "mean" (the mean over the window) or
#   "slope" (the least-squares slope over the window: a speed from a position) or "max" (the
#   largest value over the window: a deviation kept within a bound) or "line_at" (the
#   least-squares line over the window, at the reference's x = at, at = 0.0: with reference =
#   "self", a crest's place at `at` from its track after a collision against its track before,
#   the phase shift) or "period" (the mean period of the probe's oscillation about its mean
#   over the window: the span between its first and last upward crossings of that mean over
#   the periods between them; with reference = "theory:standing_wave"),
#   window_from = 0.0, window_to = 0.0 (the window in the reference's x; 0 = its last point),
#   reference = "theory:kdv": columns t (s), amplitude (m: the amplitude KdV gives the speed
#   measured over the window, W (6.16): A = 2 H (V / sqrt(g H) - 1), V the slope of crest_x),
#   crest_x (m: a line whose slope is KdV's speed of the amplitude measured, the mean of
#   crest_amplitude), width (m: KdV's width sqrt(4 H^3 / (3 A)) of that mean amplitude, W (6.17),
#   for crest_width) and zero (for crest_shape),
#   reference = "theory:still_water": columns t (s), bed_pressure (Pa, rho0 g H), water_level
#   (m, H) and zero, for the first fluid block's depth H,
#   reference = "theory:free_fall": columns t (s) and centre_y (m): the centre of mass of
#   water whose last fluid block falls freely while the others rest, from its first reading,
#   y(0) - f g t^2 / 2 with f the last block's share of the mass (until the block lands),
#   reference = "theory:standing_wave": columns t (s) and period (s): linear theory's first
#   sloshing mode of the tank between the x walls (the domain's length L), T_1 = 2 pi /
#   sqrt(g k tanh(k H)), k = pi / L, H the water's volume as laid out / L (2D; statistic =
#   "period", of probe centre_x for example),
#   reference = "self": the same statistic of the same probe over reference_from..reference_to
#   (s; reference_x and reference_y are then not used): a speed or height that must not change
#   between the passes of a periodic tank; reference_from = 0.0, reference_to = 0.0
#   reference = "run:LABEL": the same statistic over the same window of column reference_probe
#   (= "": the probe itself) of companion run LABEL (validation.companions), sampled at the
#   companion's own times: a wave's height after a collision against the same wave's alone
# [[validation.profiles]]: a field of profile.csv compared at the end time with an exact
#   solution: field = "rho" (or "p", "u"), reference = "theory:riemann" (the exact Riemann
#   solution of an ideal gas between the first two fluid blocks, the diaphragm at the first
#   block's x max), tolerance = 0.1, quick_tolerance = 0.1 (the relative L1 error
#   sum |f - f_exact| / sum |f_exact| allowed), gated = true
)toml",
                     fmt::arg("gravity", gravity), fmt::arg("zero", zero), fmt::arg("one", one),
                     fmt::arg("z_walls", z_walls));
}
}  // namespace

const std::string& case_defaults_toml(int dimension) {
  static const std::string d2 = defaults_for(2);
  static const std::string d3 = defaults_for(3);
  return dimension == 3 ? d3 : d2;
}

const std::string& fluid_block_defaults(int dimension) {
  static const std::string d2 =
      "min = [0.0, 0.0]\nmax = [1.0, 1.0]\nvelocity = [0.0, 0.0]\nhydrostatic = true\n"
      "density = 0.0\ninternal_energy = 0.0\nspacing = 0.0\n"
      "velocity_gradient = [0.0, 0.0, 0.0, 0.0]\nshape = \"box\"\nlayout = \"lattice\"\n"
      "count = 0\nseed = 1\nmin_distance = 0.0\nsurface_amplitude = 0.0\nsurface_decay = 0.0\n"
      "surface_from = \"x_min\"\nsolitary_amplitude = 0.0\nsolitary_centre = 0.0\n"
      "solitary_towards = \"x_max\"\n"
      "initial_pressure = \"none\"\n";
  static const std::string d3 =
      "min = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\nvelocity = [0.0, 0.0, 0.0]\n"
      "hydrostatic = true\ndensity = 0.0\ninternal_energy = 0.0\nspacing = 0.0\n"
      "velocity_gradient = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]\n"
      "shape = \"box\"\nlayout = \"lattice\"\ncount = 0\nseed = 1\nmin_distance = 0.0\n"
      "surface_amplitude = 0.0\nsurface_decay = 0.0\nsurface_from = \"x_min\"\n"
      "solitary_amplitude = 0.0\nsolitary_centre = 0.0\nsolitary_towards = \"x_max\"\n"
      "initial_pressure = \"none\"\n";
  return dimension == 3 ? d3 : d2;
}

const std::string& moving_wall_defaults() {
  static const std::string d = "side = \"\"\nvelocity = 0.0\namplitude = 0.0\nperiod = 0.0\n";
  return d;
}

const std::string& repulsive_wall_defaults() {
  static const std::string d =
      "from = [0.0, 0.0]\nto = [0.0, 0.0]\nforce = \"monaghan_kos\"\nspacing = 0.0\n"
      "strength = 0.0\ncutoff = 0.0\npowers = [12.0, 4.0]\nput_back_distance = 0.5\n"
      "clearance = 0.0\nreach = 0.0\n"
      "stroke = 0.0\nfrequency = 0.0\nphase = 0.0\nhinge_depth = 0.1344\n"
      "reference_height = 0.15\n";
  return d;
}

const std::string& profile_defaults() {
  static const std::string d =
      "field = \"rho\"\nreference = \"theory:riemann\"\ntolerance = 0.1\n"
      "quick_tolerance = 0.1\ngated = true\n";
  return d;
}
const std::string& curve_defaults() {
  static const std::string d =
      "probe = \"\"\nlabel = \"\"\nreference = \"\"\nreference_x = \"\"\nreference_y = \"\"\n"
      "source = \"\"\nvalue_scale = 1.0\nerror = \"relative\"\ntolerance = 0.1\n"
      "quick_tolerance = 0.1\nmean_tolerance = 0.0\nquick_mean_tolerance = 0.0\ngated = true\n"
      "statistic = \"pointwise\"\nwindow_from = 0.0\nwindow_to = 0.0\n"
      "reference_from = 0.0\nreference_to = 0.0\nat = 0.0\nreference_probe = \"\"\n";
  return d;
}

}  // namespace flume
