#include "flume/run/run_output.hpp"

#include <fmt/format.h>

#include <iostream>

#include "flume/io/atomic_file.hpp"

namespace flume {

RunOutput::RunOutput(const std::filesystem::path& dir,
                     const std::vector<std::string>& diagnostics_columns,
                     const std::vector<std::string>& probe_columns, bool quiet)
    : dir_(dir),
      quiet_(quiet),
      diagnostics_(dir / "diagnostics.csv", diagnostics_columns),
      series_(dir / "snapshots" / "snapshots.pvd") {
  if (probe_columns.size() > 1)
    probes_ = std::make_unique<io::CsvTable>(dir / "probes.csv", probe_columns);
  std::filesystem::create_directories(dir / "snapshots");
}

void RunOutput::log(const std::string& line) {
  log_ += line;
  log_ += '\n';
  if (!quiet_) std::cout << line << std::endl;
}

void RunOutput::add_snapshot(double time, const io::PointCloud& cloud) {
  const std::string file = fmt::format("snapshot_{:05d}.vtu", snapshot_count_++);
  io::write_vtu(dir_ / "snapshots" / file, cloud);
  series_.add(time, file);
}

void RunOutput::flush() const {
  diagnostics_.flush();
  if (probes_) probes_->flush();
  io::write_file_atomic(dir_ / "log.txt", log_);
}

}  // namespace flume
