// Numeric CSV tables (diagnostics.csv, probes.csv): a writer that keeps the whole table and
// rewrites it atomically on each flush, and a reader for tests, validation and post-processing.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace flume::io {

// A table of doubles written as CSV: a header line of column names, then one line per row.
// Numbers use fmt's "{:.17g}", which round-trips every double exactly (including -0, inf and
// nan), so outputs are bit-reproducible and read back to the same values.
class CsvTable {
 public:
  // Column names must be non-empty, unique and free of commas, quotes and line breaks (we do
  // not quote fields); otherwise throws std::invalid_argument.
  CsvTable(std::filesystem::path path, std::vector<std::string> columns);

  // Appends a row in memory; throws std::invalid_argument if values.size() != columns().size().
  void add_row(std::span<const double> values);

  // Rewrites the whole file atomically (header then all rows), so the file on disk is always a
  // complete table even if the run is killed.
  void flush() const;

  std::size_t rows() const { return rows_; }
  const std::vector<std::string>& columns() const { return columns_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::vector<std::string> columns_;
  // The rendered file content, kept so that flush() only has to write, not re-format.
  std::string text_;
  std::size_t rows_ = 0;
};

// A CSV file read back: column names and numeric rows (each row has columns.size() values).
struct CsvData {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  // All values of the named column; throws std::out_of_range naming the column if absent.
  std::vector<double> column(std::string_view name) const;
};

// Reads a header line plus numeric rows. Blank lines are skipped and fields are trimmed of
// whitespace. Throws std::runtime_error naming the file and line on an unreadable file, a
// malformed or out-of-range number, or a row whose length does not match the header.
CsvData read_csv(const std::filesystem::path& path);

}  // namespace flume::io
