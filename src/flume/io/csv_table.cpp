// CSV table writer and reader (see csv_table.hpp).
#include "flume/io/csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <unordered_set>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include "flume/io/atomic_file.hpp"

namespace flume::io {

namespace {

std::string_view trim(std::string_view s) {
  constexpr std::string_view kSpace = " \t\r\n\f\v";
  const auto first = s.find_first_not_of(kSpace);
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(kSpace);
  return s.substr(first, last - first + 1);
}

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    if (comma == std::string_view::npos) {
      fields.push_back(trim(line.substr(start)));
      return fields;
    }
    fields.push_back(trim(line.substr(start, comma - start)));
    start = comma + 1;
  }
}

}  // namespace

CsvTable::CsvTable(std::filesystem::path path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)) {
  if (columns_.empty()) {
    throw std::invalid_argument(
        fmt::format("CSV table '{}' needs at least one column", path_.string()));
  }
  std::unordered_set<std::string_view> seen;
  for (const auto& name : columns_) {
    if (name.empty() || name.find_first_of(",\"\r\n") != std::string::npos ||
        trim(name).size() != name.size()) {
      throw std::invalid_argument(
          fmt::format("CSV table '{}': invalid column name '{}'", path_.string(), name));
    }
    if (!seen.insert(name).second) {
      throw std::invalid_argument(
          fmt::format("CSV table '{}': duplicate column name '{}'", path_.string(), name));
    }
  }
  text_ = fmt::format("{}\n", fmt::join(columns_, ","));
}

void CsvTable::add_row(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument(fmt::format("CSV table '{}': row has {} values, expected {}",
                                            path_.string(), values.size(), columns_.size()));
  }
  auto out = std::back_inserter(text_);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text_.push_back(',');
    fmt::format_to(out, "{:.17g}", values[i]);
  }
  text_.push_back('\n');
  ++rows_;
}

void CsvTable::flush() const {
  write_file_atomic(path_, text_);
}

std::vector<double> CsvData::column(std::string_view name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) {
    throw std::out_of_range(fmt::format("CSV data has no column '{}'", name));
  }
  const auto index = static_cast<std::size_t>(it - columns.begin());
  std::vector<double> values;
  values.reserve(rows.size());
  for (const auto& row : rows)
    values.push_back(row.at(index));
  return values;
}

CsvData read_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot open CSV file '{}'", path.string()));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw std::runtime_error(fmt::format("cannot read CSV file '{}'", path.string()));
  const std::string text = std::move(buffer).str();

  CsvData data;
  bool have_header = false;
  std::size_t line_number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    auto end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string_view line = trim(std::string_view(text).substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line.empty()) continue;

    const auto fields = split_commas(line);
    if (!have_header) {
      data.columns.assign(fields.begin(), fields.end());
      have_header = true;
      continue;
    }
    if (fields.size() != data.columns.size()) {
      throw std::runtime_error(fmt::format("{}:{}: row has {} fields, header has {}", path.string(),
                                           line_number, fields.size(), data.columns.size()));
    }
    std::vector<double> row;
    row.reserve(fields.size());
    for (std::size_t i = 0; i < fields.size(); ++i) {
      std::string_view field = fields[i];
      // from_chars is locale-independent and exact, but rejects a leading '+' that other
      // tools may write.
      if (field.size() > 1 && field.front() == '+' && field[1] != '-') field.remove_prefix(1);
      double value = 0.0;
      const auto [ptr, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
      if (ec == std::errc::result_out_of_range) {
        throw std::runtime_error(fmt::format("{}:{}: number '{}' in column '{}' is out of range",
                                             path.string(), line_number, fields[i],
                                             data.columns[i]));
      }
      if (ec != std::errc() || ptr != field.data() + field.size() || field.empty()) {
        throw std::runtime_error(fmt::format("{}:{}: malformed number '{}' in column '{}'",
                                             path.string(), line_number, fields[i],
                                             data.columns[i]));
      }
      row.push_back(value);
    }
    data.rows.push_back(std::move(row));
  }
  if (!have_header) {
    throw std::runtime_error(fmt::format("CSV file '{}' has no header line", path.string()));
  }
  return data;
}

}  // namespace flume::io
