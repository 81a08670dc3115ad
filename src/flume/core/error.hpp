// The two kinds of failure a user sees, each with its own exit status (spec/contract.md):
// InputError (exit 2): the case file or command line is wrong; SimulationError (exit 1): the
// simulation itself failed (NaN, blow-up, particle lost).
#pragma once

#include <stdexcept>
#include <string>

namespace flume {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace flume
