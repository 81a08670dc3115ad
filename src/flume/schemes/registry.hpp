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
  std::string density;  // "summation" (BL (1)) or "continuity" (BL (4))
  std::string force;    // "bl7" (BL (7)), "bl20" (BL (20) = BL (8) with +), "bl59" (CSPH)
  // BL section 4: "none"; for a summation density the kernel corrections of the density,
  // "shepard" (BL (53)) or "first_order" (BL (47)-(52)); for a continuity density the corrected
  // gradient of correction.hpp, "gradient" (BL (42)-(45)), "shepard" (BL (53), (57)) or
  // "mixed" (CSPH, BL (54)-(58)).
  std::string correction = "none";
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
