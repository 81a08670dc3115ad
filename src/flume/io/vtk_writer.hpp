// ParaView output of particle clouds: VTK XML UnstructuredGrid (.vtu) snapshots and the .pvd
// collection that strings them into a time series (the run's snapshots/ directory).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace flume::io {

// One per-point array: `components` is 1 (scalar) or 3 (vector); data holds n * components
// values, point-major (x0 y0 z0 x1 y1 z1 ...).
struct PointField {
  std::string name;
  int components = 1;
  std::vector<double> data;
};

// A cloud of n points: xyz holds 3 n coordinates (z = 0 in 2D). ids, if non-empty, has n
// entries and is written as an Int64 array named "id".
struct PointCloud {
  std::vector<double> xyz;
  std::vector<PointField> fields;
  std::vector<std::int64_t> ids;
};

// Writes `cloud` atomically as a VTK XML UnstructuredGrid with one VTK_VERTEX cell per point.
// Arrays are raw little-endian binary in an <AppendedData> block (header_type UInt64): compact
// and exact. Throws std::invalid_argument if array sizes are inconsistent, a field has other
// than 1 or 3 components, or names are empty or repeated; std::runtime_error if writing fails.
void write_vtu(const std::filesystem::path& path, const PointCloud& cloud);

// A ParaView .pvd collection: each add() appends a (time, file) entry and rewrites the whole
// .pvd atomically, so it always lists exactly the snapshots written so far.
class PvdSeries {
 public:
  explicit PvdSeries(std::filesystem::path pvd_path);

  // `relative_file` is relative to the .pvd's directory, as ParaView resolves it. Throws
  // std::invalid_argument if time is not finite.
  void add(double time, const std::string& relative_file);

  const std::filesystem::path& path() const { return pvd_path_; }
  const std::vector<std::pair<double, std::string>>& entries() const { return entries_; }

 private:
  std::filesystem::path pvd_path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace flume::io
