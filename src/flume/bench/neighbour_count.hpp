// The mean number of neighbours per particle (other particles closer than a radius), counted
// independently of flume's own neighbour search: `flume bench` reports it to turn particle-steps
// into interactions, and must not depend on the search it is measuring (which may change).
#pragma once

#include <span>

#include "flume/core/vec.hpp"

namespace flume {

// Mean over the particles of the number of *other* particles at distance < radius. O(N): the
// particles are binned into cells of side `radius` over their bounding box, so only the 3^D
// cells around each particle are searched. Serial on purpose: it runs once per benchmark, after
// the timed steps, and stays deterministic. Returns 0 for an empty set.
template <int D>
double mean_neighbour_count(std::span<const Vec<D>> x, double radius);

extern template double mean_neighbour_count<2>(std::span<const Vec<2>>, double);
extern template double mean_neighbour_count<3>(std::span<const Vec<3>>, double);

}  // namespace flume
