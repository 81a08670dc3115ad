#include "flume/run/run_output.hpp"

#include <fmt/format.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "flume/io/atomic_file.hpp"

namespace flume {

namespace {

std::string snapshot_file(int k) {
  return fmt::format("snapshot_{:05d}.vtu", k);
}

// The first `rows` rows of a table the run wrote, added again: "{:.17g}" round-trips, so the
// text is the same byte for byte.
void restore_rows(io::CsvTable& table, std::int64_t rows) {
  const auto data = io::read_csv(table.path());
  if (data.columns != table.columns() || static_cast<std::int64_t>(data.rows.size()) < rows)
    throw std::runtime_error(fmt::format(
        "{}: does not hold the {} rows of the checkpoint (the run directory was changed)",
        table.path().string(), rows));
  for (std::int64_t r = 0; r < rows; ++r)
    table.add_row(data.rows[static_cast<std::size_t>(r)]);
}

}  // namespace

RunOutput::RunOutput(const std::filesystem::path& dir,
                     const std::vector<std::string>& diagnostics_columns,
                     const std::vector<std::string>& probe_columns, bool quiet,
                     const OutputState* resume)
    : dir_(dir),
      quiet_(quiet),
      diagnostics_(dir / "diagnostics.csv", diagnostics_columns),
      series_(dir / "snapshots" / "snapshots.pvd") {
  if (probe_columns.size() > 1)
    probes_ = std::make_unique<io::CsvTable>(dir / "probes.csv", probe_columns);
  std::filesystem::create_directories(dir / "snapshots");
  if (!resume) return;
  std::ifstream old_log(dir / "log.txt");
  std::stringstream text;
  text << old_log.rdbuf();
  log_ = text.str();
  restore_rows(diagnostics_, resume->diagnostics_rows);
  if (probes_) restore_rows(*probes_, resume->probe_rows);
  for (double t : resume->snapshot_times)
    series_.add(t, snapshot_file(snapshot_count_++));
  // The snapshots written after the checkpoint: the resumed run writes them again.
  for (int k = snapshot_count_;; ++k) {
    std::error_code ec;
    if (!std::filesystem::remove(dir / "snapshots" / snapshot_file(k), ec)) break;
  }
}

void RunOutput::log(const std::string& line) {
  note(line);
  if (!quiet_) std::cout << line << std::endl;
}

void RunOutput::note(const std::string& line) {
  log_ += line;
  log_ += '\n';
}

void RunOutput::add_snapshot(double time, const io::PointCloud& cloud) {
  const std::string file = snapshot_file(snapshot_count_++);
  io::write_vtu(dir_ / "snapshots" / file, cloud);
  series_.add(time, file);
}

std::vector<double> RunOutput::snapshot_times() const {
  std::vector<double> times;
  for (const auto& [t, file] : series_.entries())
    times.push_back(t);
  return times;
}

void RunOutput::flush() const {
  diagnostics_.flush();
  if (probes_) probes_->flush();
  io::write_file_atomic(dir_ / "log.txt", log_);
}

}  // namespace flume
