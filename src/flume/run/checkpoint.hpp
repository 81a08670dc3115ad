// Checkpoints: everything a run needs to continue bit-identically, in one HDF5 file
// (checkpoints/checkpoint_<step>.h5 in the run directory), self-describing for h5py:
//   /                 attributes format = "flume checkpoint", format_version, flume_version,
//                     case_name, dimension, checksum_fnv1a64
//   /case_toml        the resolved case (the run's case.toml)
//   /state/...        time, step, last_dt, first_dt, leapfrog_dt_prev (scalars, "unit" attribute)
//   /output/...       next_output, next_snapshot, diagnostics_rows, probe_rows,
//                     snapshot_times, probe_state: where the run directory's files stood
//   /particles/<name> every state field the run carries (ParticleSet::for_each_named_state_field:
//                     the scheme's optional ones included), shape (n), (n, D) or (n, D, D), its
//                     unit an attribute; the group's attribute optional_fields names the set.
// The checksum (64-bit FNV-1a) runs over every value in the order the file lists them, so a
// file that HDF5 still opens but whose data changed is caught too. Written to a temporary name
// and renamed, like every output (io/atomic_file.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "flume/core/particle_set.hpp"
#include "flume/sim/simulation_state.hpp"

namespace flume {

// Where the run's output files stood at the checkpoint: resume truncates them back to it.
struct OutputState {
  std::int64_t next_output = 1;  // the next diagnostics row is due at next_output * interval
  std::int64_t next_snapshot = 1;
  std::int64_t diagnostics_rows = 0;  // rows of diagnostics.csv and probes.csv written
  std::int64_t probe_rows = 0;
  std::vector<double> snapshot_times;  // the times of the snapshots written, s
  std::vector<double> probe_state;     // the probes' own memory (CaseProbes::state)
};

template <int D>
struct Checkpoint {
  std::string case_toml;
  std::string case_name;
  SimulationState state;
  OutputState output;
  ParticleSet<D> particles;  // real particles only; the optional fields in use
};

// A checkpoint that cannot be used: unreadable, truncated, of another format or dimension, or
// whose checksum does not match.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes atomically (temporary name, then rename). Throws std::runtime_error on I/O failure.
template <int D>
void write_checkpoint(const std::filesystem::path& path, const Checkpoint<D>& c);

// Reads and verifies; throws CheckpointError saying what is wrong.
template <int D>
Checkpoint<D> read_checkpoint(const std::filesystem::path& path);

// The dimension a checkpoint was written for (throws CheckpointError).
int checkpoint_dimension(const std::filesystem::path& path);

// The checkpoint files of a run directory, oldest first (by the step in their names).
std::vector<std::filesystem::path> list_checkpoints(const std::filesystem::path& run_dir);

// The file name of the checkpoint at a step, in run_dir/checkpoints/.
std::filesystem::path checkpoint_path(const std::filesystem::path& run_dir, long step);

// Deletes all but the newest `keep` checkpoints.
void prune_checkpoints(const std::filesystem::path& run_dir, int keep);

}  // namespace flume
