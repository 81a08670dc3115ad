// The named registry at the edge: presets of spec/methods.md resolved to their (density, force)
// rows, and the one runtime-to-template step that builds a scheme for a kernel.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "flume/kernels/kernel.hpp"
#include "flume/schemes/scheme.hpp"

namespace flume {

struct SchemeRows {
  // "summation" (BL (1)), "continuity" (BL (4)), "w350" (W (3.50)), "w379" (W (3.79) corrected)
  std::string density;
  // "bl7" (BL (7)), "bl20" (BL (20) = BL (8) with +), "bl59" (CSPH), "w351" (W (3.51) with the
  // energy equation W (3.52)), "w380" (W (3.80) with W (3.81))
  std::string force;
  // BL section 4: "none"; for a summation density the kernel corrections of the density,
  // "shepard" (BL (53)) or "first_order" (BL (47)-(52)); for a continuity density the corrected
  // gradient of correction.hpp, "gradient" (BL (42)-(45)), "shepard" (BL (53), (57)) or
  // "mixed" (CSPH, BL (54)-(58)); for W's weak scheme "renormalized" (R-SPH, W (4.8)-(4.16)).
  std::string correction = "none";
  // W (2.22): "fixed" or "evolving" (the evolved-density schemes of W: sph-euler, wsph, rsph).
  std::string smoothing_length = "fixed";
  // The sub-grid model: "none", or "smagorinsky" (LES-SPH, W (5.31)-(5.34)); it acts through
  // Physics (its stress enters BL (24)'s pair form), so it does not pick a scheme class.
  std::string turbulence = "none";
};

// The rows of a named preset, or nullopt for an unknown name.
std::optional<SchemeRows> preset_rows(const std::string& preset);
const std::vector<std::string>& preset_names();
// The (density, force, correction) rows that have a scheme, as "density+force+correction".
const std::vector<std::string>& scheme_combinations();

// Builds the scheme for these rows; throws InputError for a combination without a scheme.
template <int D>
std::unique_ptr<Scheme<D>> make_scheme(const SchemeRows& rows, KernelKind kernel,
                                       const Physics<D>& phys);

}  // namespace flume
