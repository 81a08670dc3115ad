// The files of one run directory, kept open for the run: the log, the CSV tables and the
// snapshot series. Every flush rewrites a whole file atomically. A resumed run opens them as a
// checkpoint left them (run/checkpoint.hpp): the rows and snapshots written after it are dropped,
// so the files go on exactly as an uninterrupted run's.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "flume/io/csv_table.hpp"
#include "flume/io/vtk_writer.hpp"
#include "flume/run/checkpoint.hpp"

namespace flume {

class RunOutput {
 public:
  // A new run directory, or (resume non-null) the one a checkpoint describes.
  RunOutput(const std::filesystem::path& dir, const std::vector<std::string>& diagnostics_columns,
            const std::vector<std::string>& probe_columns, bool quiet,
            const OutputState* resume = nullptr);

  void log(const std::string& line);   // to log.txt and, unless quiet, to stdout
  void note(const std::string& line);  // to log.txt only
  void add_diagnostics(const std::vector<double>& row) { diagnostics_.add_row(row); }
  void add_probes(const std::vector<double>& row) {
    if (probes_) probes_->add_row(row);
  }
  void add_snapshot(double time, const io::PointCloud& cloud);
  void flush() const;  // diagnostics, probes, log
  const std::filesystem::path& dir() const { return dir_; }

  // Where the files stand (what a checkpoint records).
  std::size_t diagnostics_rows() const { return diagnostics_.rows(); }
  std::size_t probe_rows() const { return probes_ ? probes_->rows() : 0; }
  std::vector<double> snapshot_times() const;

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
