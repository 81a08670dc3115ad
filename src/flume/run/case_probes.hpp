// The measurements a case's [probes] ask for, as the columns of probes.csv: what each column
// is, one row at a time, and the probes' memory (kept in a checkpoint, so that a resumed run
// writes the rows an uninterrupted one would).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "flume/case/case_spec.hpp"
#include "flume/probes/breaking.hpp"
#include "flume/probes/semi_axes.hpp"
#include "flume/probes/wave_probes.hpp"
#include "flume/sim/simulation.hpp"

namespace flume {

template <int D>
class CaseProbes {
 public:
  explicit CaseProbes(const CaseSpec& spec);

  // "time" and then each probe's columns, in the order of row().
  std::vector<std::string> columns() const;
  std::vector<double> row(const Simulation<D>& sim);

  // The semi-axes probe's reference moments, the crest tracker's last position and the
  // breaking time, each preceded by its length.
  std::vector<double> state() const;
  void restore(const std::vector<double>& s);

 private:
  const CaseSpec& spec_;
  std::optional<SemiAxesProbe> semi_axes_;
  std::optional<WaveProbe> waves_;
  std::optional<BreakingProbe> breaking_;
  std::optional<ShoalingProbe> shoaling_;
  std::vector<double> bed_;  // the beaches' heights under the depth profile's columns (or empty)
};

extern template class CaseProbes<2>;
extern template class CaseProbes<3>;

}  // namespace flume
