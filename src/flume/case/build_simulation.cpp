#include "flume/case/build_simulation.hpp"

#include <cmath>

#include "flume/core/error.hpp"
#include "flume/kernels/kernel.hpp"
#include "flume/schemes/registry.hpp"

namespace flume {

namespace {
template <int D>
Vec<D> to_vec(const std::vector<double>& v) {
  Vec<D> out;
  for (int k = 0; k < D; ++k)
    out[k] = v[static_cast<std::size_t>(k)];
  return out;
}

WallKind wall_kind(const std::string& s) {
  if (s == "no_slip") return WallKind::no_slip;
  if (s == "open") return WallKind::open;
  return WallKind::free_slip;
}
}  // namespace

template <int D>
Physics<D> build_physics(const CaseSpec& spec) {
  Physics<D> phys;
  phys.eos.rho0 = spec.rho0;
  phys.eos.gamma = spec.gamma;
  phys.eos.kappa = spec.bulk_modulus;
  phys.mu = spec.mu;
  phys.gravity = to_vec<D>(spec.gravity);
  phys.av_alpha = spec.alpha;
  phys.av_beta = spec.beta;
  return phys;
}

template <int D>
ParticleSet<D> build_particles(const CaseSpec& spec, const Physics<D>& phys) {
  ParticleSet<D> ps;
  // No optional field yet: the Simulation allocates those its scheme uses (use_only). Filled
  // here, they would set the peak memory of the run (128 bytes a particle in 2D).
  ps.optional = 0;
  const double dx = spec.spacing;
  const double g = norm(phys.gravity);
  const double h = spec.h_over_dx * dx;
  std::int64_t next_id = 0;
  // A block of width L holds floor(L/dx) particles per row; the tolerance absorbs the round-off
  // of spacings given as L/n.
  auto counts = [dx](const FluidBlock& block) {
    std::array<long, D> count{};
    for (int k = 0; k < D; ++k)
      count[k] = static_cast<long>(std::floor((block.max[k] - block.min[k]) / dx + 1e-6));
    return count;
  };
  std::size_t particles = 0;  // reserved up front: growth by doubling would inflate the peak memory
  for (const auto& block : spec.blocks) {
    std::size_t n = 1;
    for (const long c : counts(block))
      n *= static_cast<std::size_t>(c);
    particles += n;
  }
  ps.reserve(particles);
  for (const auto& block : spec.blocks) {
    const std::array<long, D> count = counts(block);
    long total = 1;
    for (int k = 0; k < D; ++k)
      total *= count[k];
    const double top = block.max[D - 1];
    std::array<long, D> idx{};
    for (long n = 0; n < total; ++n) {
      long rest = n;
      for (int k = 0; k < D; ++k) {
        idx[k] = rest % count[k];
        rest /= count[k];
      }
      Vec<D> x;
      for (int k = 0; k < D; ++k)
        x[k] = block.min[k] + (static_cast<double>(idx[k]) + 0.5) * dx;
      const double rho =
          block.hydrostatic ? phys.eos.hydrostatic_density(g * (top - x[D - 1])) : phys.eos.rho0;
      ps.add_real(next_id++, x, to_vec<D>(block.velocity), rho * std::pow(dx, D), rho, h);
    }
  }
  return ps;
}

template <int D>
Simulation<D> build_simulation(const CaseSpec& spec) {
  const Physics<D> phys = build_physics<D>(spec);
  BoxWalls<D> walls;
  walls.lo = to_vec<D>(spec.domain_min);
  walls.hi = to_vec<D>(spec.domain_max);
  for (int k = 0; k < D; ++k) {
    walls.kind[k][0] = wall_kind(spec.walls[static_cast<std::size_t>(2 * k)]);
    walls.kind[k][1] = wall_kind(spec.walls[static_cast<std::size_t>(2 * k + 1)]);
  }
  auto scheme = make_scheme<D>(SchemeRows{spec.density, spec.force, spec.correction},
                               *kernel_from_name(spec.kernel), phys);
  SimulationConfig<D> config;
  config.cfl = spec.cfl;
  config.fixed_dt = spec.dt;
  config.shepard_every = spec.shepard_every;
  return Simulation<D>(build_particles<D>(spec, phys), walls, std::move(scheme), phys, config);
}

template Physics<2> build_physics<2>(const CaseSpec&);
template Physics<3> build_physics<3>(const CaseSpec&);
template ParticleSet<2> build_particles<2>(const CaseSpec&, const Physics<2>&);
template ParticleSet<3> build_particles<3>(const CaseSpec&, const Physics<3>&);
template Simulation<2> build_simulation<2>(const CaseSpec&);
template Simulation<3> build_simulation<3>(const CaseSpec&);

}  // namespace flume
