// What a Simulation carries between steps besides its particles: the clock, the step rule's
// memory and leap-frog's history. With the particles' state fields it is all a run needs to go
// on bit-identically (run/checkpoint.hpp).
#pragma once

#include <cstdint>

namespace flume {

struct SimulationState {
  double time = 0.0;              // s
  std::int64_t steps = 0;         // steps taken
  double last_dt = 0.0;           // the last step taken, s
  double first_dt = 0.0;          // the step rule's first value (the collapse check's scale), s
  double leapfrog_dt_prev = 0.0;  // dt^n of BL (61)'s dt_bar = (dt^n + dt^{n+1}) / 2, s
};

}  // namespace flume
