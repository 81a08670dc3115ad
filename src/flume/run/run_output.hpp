// The files of one run directory, kept open for the run: the log, the CSV tables and the
// snapshot series. Every flush rewrites a whole file atomically.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "flume/io/csv_table.hpp"
#include "flume/io/vtk_writer.hpp"

namespace flume {

class RunOutput {
 public:
  RunOutput(const std::filesystem::path& dir, const std::vector<std::string>& diagnostics_columns,
            const std::vector<std::string>& probe_columns, bool quiet);

  void log(const std::string& line);  // to log.txt and, unless quiet, to stdout
  void add_diagnostics(const std::vector<double>& row) { diagnostics_.add_row(row); }
  void add_probes(const std::vector<double>& row) {
    if (probes_) probes_->add_row(row);
  }
  void add_snapshot(double time, const io::PointCloud& cloud);
  void flush() const;  // diagnostics, probes, log
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
  bool quiet_;
  std::string log_;
  io::CsvTable diagnostics_;
  std::unique_ptr<io::CsvTable> probes_;
  io::PvdSeries series_;
  int snapshot_count_ = 0;
};

}  // namespace flume
