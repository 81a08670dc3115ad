// Copying the state fields (ParticleSet::for_each_named_state_field) of the first n particles
// from one set to another carrying the same fields: what a checkpoint takes from a run and
// gives back to it (run/checkpoint.hpp, Simulation::restore).
#pragma once

#include <cstddef>
#include <type_traits>
#include <vector>

#include "flume/core/particle_set.hpp"

namespace flume {

// `to` must use the same optional fields as `from`: the one list then visits the same arrays,
// of the same types, in the same order. Each of to's arrays becomes from's first n entries.
template <int D>
void copy_state_fields(const ParticleSet<D>& from, ParticleSet<D>& to, std::size_t n) {
  std::vector<const void*> sources;
  // for_each_state_field is not const; it only hands out the arrays, read here.
  const_cast<ParticleSet<D>&>(from).for_each_state_field([&](auto& f) { sources.push_back(&f); });
  std::size_t k = 0;
  to.for_each_state_field([&](auto& f) {
    const auto& in = *static_cast<const std::decay_t<decltype(f)>*>(sources[k++]);
    f.assign(in.begin(), in.begin() + static_cast<long>(n));
  });
}

}  // namespace flume
