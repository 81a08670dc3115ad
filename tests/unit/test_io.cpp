// Unit tests for the I/O layer: atomic writes, bit-exact CSV round trips, and .vtu/.pvd output
// that decodes back to exactly what was written.
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "flume/io/atomic_file.hpp"
#include "flume/io/csv_table.hpp"
#include "flume/io/vtk_writer.hpp"

namespace flume::io {
namespace {

namespace fs = std::filesystem;

// Gives each test its own empty directory, removed afterwards.
class Io : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("flume_test_io_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

  std::vector<fs::path> files_in_dir() const {
    std::vector<fs::path> out;
    for (const auto& entry : fs::directory_iterator(dir_))
      out.push_back(entry.path().filename());
    return out;
  }

  fs::path dir_;
};

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::uint64_t decode_u64(const std::string& bytes, std::size_t at) {
  std::uint64_t value = 0;
  for (int i = 7; i >= 0; --i) {
    value = (value << 8) | static_cast<unsigned char>(bytes.at(at + static_cast<std::size_t>(i)));
  }
  return value;
}

double decode_f64(const std::string& bytes, std::size_t at) {
  return std::bit_cast<double>(decode_u64(bytes, at));
}

// The message of the std::runtime_error that read_csv throws, or "" if it does not throw.
std::string read_csv_error(const fs::path& path) {
  try {
    read_csv(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST_F(Io, AtomicWriteCreatesFileAndLeavesNoTemporary) {
  const auto path = dir_ / "out.txt";
  write_file_atomic(path, "hello\n");
  EXPECT_EQ(read_bytes(path), "hello\n");
  EXPECT_EQ(files_in_dir(), std::vector<fs::path>{"out.txt"});
}

TEST_F(Io, AtomicWriteReplacesExistingContent) {
  const auto path = dir_ / "out.txt";
  write_text(path, "a much longer old content that must disappear entirely\n");
  write_file_atomic(path, "new");
  EXPECT_EQ(read_bytes(path), "new");
  write_file_atomic(path, "");
  EXPECT_EQ(read_bytes(path), "");
  EXPECT_EQ(files_in_dir(), std::vector<fs::path>{"out.txt"});
}

TEST_F(Io, AtomicWriteKeepsBinaryBytes) {
  const std::string content("a\0b\r\n\xff", 6);
  write_file_atomic(dir_ / "bin", content);
  EXPECT_EQ(read_bytes(dir_ / "bin"), content);
}

TEST_F(Io, AtomicWriteFailureNamesFileAndCleansUp) {
  const auto path = dir_ / "missing_dir" / "out.txt";
  try {
    write_file_atomic(path, "x");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  // Renaming onto a directory fails after the temporary was written: it must be removed.
  fs::create_directory(dir_ / "a_dir");
  fs::create_directory(dir_ / "a_dir" / "child");
  EXPECT_THROW(write_file_atomic(dir_ / "a_dir", "x"), std::runtime_error);
  EXPECT_EQ(files_in_dir(), std::vector<fs::path>{"a_dir"});
}

TEST_F(Io, CsvRoundTripIsBitExact) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::vector<double> awkward = {1.0 / 3.0,
                                       1e-300,
                                       -0.0,
                                       6.02e23,
                                       std::numeric_limits<double>::max(),
                                       std::numeric_limits<double>::lowest(),
                                       std::numeric_limits<double>::denorm_min(),
                                       std::numeric_limits<double>::min(),
                                       0.1 + 0.2,
                                       -kInf,
                                       kInf,
                                       123456789012345678.0};
  std::vector<std::string> columns;
  for (std::size_t i = 0; i < awkward.size(); ++i)
    columns.push_back("c" + std::to_string(i));

  CsvTable table(dir_ / "t.csv", columns);
  table.add_row(awkward);
  std::vector<double> reversed(awkward.rbegin(), awkward.rend());
  table.add_row(reversed);
  table.flush();
  EXPECT_EQ(table.rows(), 2u);
  EXPECT_EQ(table.columns(), columns);

  const CsvData data = read_csv(dir_ / "t.csv");
  EXPECT_EQ(data.columns, columns);
  ASSERT_EQ(data.rows.size(), 2u);
  for (std::size_t i = 0; i < awkward.size(); ++i) {
    // Compare bit patterns: this also checks that -0.0 keeps its sign.
    EXPECT_EQ(std::bit_cast<std::uint64_t>(data.rows[0][i]),
              std::bit_cast<std::uint64_t>(awkward[i]))
        << "column " << i << " value " << awkward[i];
    EXPECT_EQ(std::bit_cast<std::uint64_t>(data.rows[1][i]),
              std::bit_cast<std::uint64_t>(reversed[i]));
  }
  EXPECT_TRUE(std::signbit(data.column("c2")[0]));
  EXPECT_EQ(files_in_dir(), std::vector<fs::path>{"t.csv"});
}

TEST_F(Io, CsvNanRoundTripsAsNan) {
  CsvTable table(dir_ / "t.csv", {"x"});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  table.add_row(std::span<const double>(&nan, 1));
  table.flush();
  EXPECT_TRUE(std::isnan(read_csv(dir_ / "t.csv").rows.at(0).at(0)));
}

TEST_F(Io, CsvFileFormat) {
  CsvTable table(dir_ / "t.csv", {"time", "step"});
  table.flush();  // header only
  EXPECT_EQ(read_bytes(dir_ / "t.csv"), "time,step\n");
  table.add_row(std::vector<double>{0.5, 3.0});
  table.add_row(std::vector<double>{1e-7, 4.0});
  table.flush();
  EXPECT_EQ(read_bytes(dir_ / "t.csv"), "time,step\n0.5,3\n9.9999999999999995e-08,4\n");
}

TEST_F(Io, CsvFlushRewritesWholeFile) {
  CsvTable table(dir_ / "t.csv", {"a"});
  for (int i = 0; i < 5; ++i) {
    table.add_row(std::vector<double>{static_cast<double>(i)});
    table.flush();
    EXPECT_EQ(read_csv(dir_ / "t.csv").rows.size(), static_cast<std::size_t>(i + 1));
  }
  EXPECT_EQ(read_csv(dir_ / "t.csv").column("a"), (std::vector<double>{0, 1, 2, 3, 4}));
}

TEST_F(Io, CsvWrongRowLengthThrows) {
  CsvTable table(dir_ / "t.csv", {"a", "b", "c"});
  EXPECT_THROW(table.add_row(std::vector<double>{1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(table.add_row(std::vector<double>{1.0, 2.0, 3.0, 4.0}), std::invalid_argument);
  EXPECT_THROW(table.add_row(std::vector<double>{}), std::invalid_argument);
  EXPECT_EQ(table.rows(), 0u);
  table.add_row(std::vector<double>{1.0, 2.0, 3.0});
  EXPECT_EQ(table.rows(), 1u);
}

TEST_F(Io, CsvRejectsBadColumnNames) {
  EXPECT_THROW(CsvTable(dir_ / "t.csv", {}), std::invalid_argument);
  EXPECT_THROW(CsvTable(dir_ / "t.csv", {"a", ""}), std::invalid_argument);
  EXPECT_THROW(CsvTable(dir_ / "t.csv", {"a,b"}), std::invalid_argument);
  EXPECT_THROW(CsvTable(dir_ / "t.csv", {"a\n"}), std::invalid_argument);
  EXPECT_THROW(CsvTable(dir_ / "t.csv", {"a", "a"}), std::invalid_argument);
}

TEST_F(Io, CsvReaderTrimsAndSkipsBlankLines) {
  write_text(dir_ / "t.csv", "\n  x , y\r\n\n 1.5 ,\t-2\r\n   \n+3,4e2\n5,6");  // no final '\n'
  const CsvData data = read_csv(dir_ / "t.csv");
  EXPECT_EQ(data.columns, (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(data.column("x"), (std::vector<double>{1.5, 3.0, 5.0}));
  EXPECT_EQ(data.column("y"), (std::vector<double>{-2.0, 400.0, 6.0}));
}

TEST_F(Io, CsvReaderErrorsNameFileAndLine) {
  const auto path = dir_ / "bad.csv";
  // Line 4 is the bad one (line 2 is blank and still counts).
  write_text(path, "a,b\n\n1,2\n3,zz\n");
  std::string message = read_csv_error(path);
  EXPECT_NE(message.find(path.string() + ":4"), std::string::npos) << message;
  EXPECT_NE(message.find("zz"), std::string::npos) << message;
  EXPECT_NE(message.find("'b'"), std::string::npos) << message;

  for (const std::string bad : {"1.5x", "", "1e", "--1", "+-1", "1 2", "0x10"}) {
    write_text(path, "a,b\n1," + bad + "\n");
    message = read_csv_error(path);
    EXPECT_NE(message.find(path.string() + ":2"), std::string::npos)
        << "'" << bad << "': " << message;
  }

  write_text(path, "a,b\n1,2\n1,2,3\n");
  message = read_csv_error(path);
  EXPECT_NE(message.find(path.string() + ":3"), std::string::npos) << message;

  write_text(path, "a\n1e999\n");
  message = read_csv_error(path);
  EXPECT_NE(message.find(path.string() + ":2"), std::string::npos) << message;
  EXPECT_NE(message.find("out of range"), std::string::npos) << message;

  write_text(path, "\n\n");
  EXPECT_NE(read_csv_error(path), "");
  EXPECT_NE(read_csv_error(dir_ / "does_not_exist.csv").find("does_not_exist.csv"),
            std::string::npos);
}

TEST_F(Io, CsvMissingColumnThrowsWithName) {
  write_text(dir_ / "t.csv", "a\n1\n");
  try {
    read_csv(dir_ / "t.csv").column("pressure");
    FAIL() << "expected std::out_of_range";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("pressure"), std::string::npos) << e.what();
  }
}

// The XML attributes of the <DataArray> whose Name is `name`, as text (for find()).
std::string data_array_tag(const std::string& file, const std::string& name) {
  const auto at = file.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return "";
  const auto begin = file.rfind('<', at);
  return file.substr(begin, file.find('>', at) - begin + 1);
}

std::size_t offset_of(const std::string& tag) {
  const auto at = tag.find("offset=\"");
  return std::stoul(tag.substr(at + 8));
}

TEST_F(Io, VtuDecodesBackToWhatWasWritten) {
  PointCloud cloud;
  cloud.xyz = {0.0, 1.0 / 3.0, 0.0, -2.5, 1e-300, 0.0, 6.02e23, -0.0, 7.0};
  cloud.fields.push_back({"density", 1, {1000.0, 1000.5, 999.25}});
  cloud.fields.push_back({"velocity", 3, {1, 2, 3, 4, 5, 6, 7, 8, 9}});
  cloud.ids = {10, -1, 1234567890123};
  const auto path = dir_ / "snap.vtu";
  write_vtu(path, cloud);
  EXPECT_EQ(files_in_dir(), std::vector<fs::path>{"snap.vtu"});

  const std::string file = read_bytes(path);
  const auto marker = file.find("<AppendedData encoding=\"raw\">");
  ASSERT_NE(marker, std::string::npos);
  const std::string header = file.substr(0, marker);
  EXPECT_NE(header.find("type=\"UnstructuredGrid\""), std::string::npos);
  EXPECT_NE(header.find("byte_order=\"LittleEndian\""), std::string::npos);
  EXPECT_NE(header.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(header.find("NumberOfPoints=\"3\""), std::string::npos);
  EXPECT_NE(header.find("NumberOfCells=\"3\""), std::string::npos);
  for (const std::string name :
       {"Points", "density", "velocity", "id", "connectivity", "offsets", "types"}) {
    EXPECT_NE(data_array_tag(header, name), "") << name;
  }
  EXPECT_NE(data_array_tag(header, "velocity").find("NumberOfComponents=\"3\""), std::string::npos);
  EXPECT_NE(data_array_tag(header, "density").find("type=\"Float64\""), std::string::npos);
  EXPECT_NE(data_array_tag(header, "id").find("type=\"Int64\""), std::string::npos);
  EXPECT_NE(data_array_tag(header, "types").find("type=\"UInt8\""), std::string::npos);

  const std::size_t base = file.find('_', marker) + 1;
  ASSERT_GT(base, marker);

  // The first array is Points: byte count, then the coordinates bit for bit.
  ASSERT_EQ(offset_of(data_array_tag(header, "Points")), 0u);
  ASSERT_EQ(decode_u64(file, base), cloud.xyz.size() * 8);
  for (std::size_t i = 0; i < cloud.xyz.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(decode_f64(file, base + 8 + 8 * i)),
              std::bit_cast<std::uint64_t>(cloud.xyz[i]))
        << i;
  }

  // Every other array sits at its declared offset with the right size and content.
  auto check_f64 = [&](const std::string& name, const std::vector<double>& expected) {
    const std::size_t at = base + offset_of(data_array_tag(header, name));
    ASSERT_EQ(decode_u64(file, at), expected.size() * 8) << name;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      EXPECT_EQ(decode_f64(file, at + 8 + 8 * i), expected[i]) << name << " " << i;
    }
  };
  check_f64("density", cloud.fields[0].data);
  check_f64("velocity", cloud.fields[1].data);
  auto check_i64 = [&](const std::string& name, const std::vector<std::int64_t>& expected) {
    const std::size_t at = base + offset_of(data_array_tag(header, name));
    ASSERT_EQ(decode_u64(file, at), expected.size() * 8) << name;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      EXPECT_EQ(static_cast<std::int64_t>(decode_u64(file, at + 8 + 8 * i)), expected[i])
          << name << " " << i;
    }
  };
  check_i64("id", cloud.ids);
  check_i64("connectivity", {0, 1, 2});
  check_i64("offsets", {1, 2, 3});
  const std::size_t types_at = base + offset_of(data_array_tag(header, "types"));
  ASSERT_EQ(decode_u64(file, types_at), 3u);
  EXPECT_EQ(file.substr(types_at + 8, 3), std::string("\x01\x01\x01"));

  // The binary block is followed by the closing tags and nothing else.
  const std::size_t end = types_at + 8 + 3;
  std::size_t last_array_end = end;
  for (const auto& name : {"density", "velocity", "id"}) {
    const std::size_t at = base + offset_of(data_array_tag(header, name));
    last_array_end = std::max(last_array_end, at + 8 + decode_u64(file, at));
  }
  EXPECT_EQ(file.substr(last_array_end), "\n  </AppendedData>\n</VTKFile>\n");
}

TEST_F(Io, VtuWithoutIdsOrFieldsAndEmptyCloud) {
  PointCloud cloud;
  cloud.xyz = {1, 2, 0};
  write_vtu(dir_ / "a.vtu", cloud);
  const std::string a = read_bytes(dir_ / "a.vtu");
  EXPECT_EQ(a.find("Name=\"id\""), std::string::npos);
  EXPECT_NE(a.find("NumberOfPoints=\"1\""), std::string::npos);

  write_vtu(dir_ / "empty.vtu", PointCloud{});
  EXPECT_NE(read_bytes(dir_ / "empty.vtu").find("NumberOfPoints=\"0\""), std::string::npos);
}

TEST_F(Io, VtuRejectsInconsistentClouds) {
  const auto path = dir_ / "bad.vtu";
  PointCloud cloud;
  cloud.xyz = {0, 0, 0, 1, 1};
  EXPECT_THROW(write_vtu(path, cloud), std::invalid_argument);
  cloud.xyz = {0, 0, 0, 1, 1, 0};
  cloud.fields = {{"p", 1, {1.0}}};
  EXPECT_THROW(write_vtu(path, cloud), std::invalid_argument);
  cloud.fields = {{"p", 2, {1, 2, 3, 4}}};
  EXPECT_THROW(write_vtu(path, cloud), std::invalid_argument);
  cloud.fields = {{"p", 1, {1, 2}}, {"p", 1, {1, 2}}};
  EXPECT_THROW(write_vtu(path, cloud), std::invalid_argument);
  cloud.fields = {{"id", 1, {1, 2}}};
  cloud.ids = {1, 2};
  EXPECT_THROW(write_vtu(path, cloud), std::invalid_argument);
  cloud.fields = {};
  cloud.ids = {1};
  EXPECT_THROW(write_vtu(path, cloud), std::invalid_argument);
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(Io, PvdSeriesListsAllFilesInOrder) {
  const auto path = dir_ / "snapshots.pvd";
  PvdSeries series(path);
  series.add(0.0, "snapshots/step_000000.vtu");
  series.add(1.0 / 3.0, "snapshots/step_000010.vtu");
  series.add(2.5, "snapshots/a&b.vtu");
  EXPECT_EQ(series.entries().size(), 3u);

  const std::string pvd = read_bytes(path);
  EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
  const std::vector<std::string> expected = {
      "<DataSet timestep=\"0\" part=\"0\" file=\"snapshots/step_000000.vtu\"/>",
      "<DataSet timestep=\"0.33333333333333331\" part=\"0\" "
      "file=\"snapshots/step_000010.vtu\"/>",
      "<DataSet timestep=\"2.5\" part=\"0\" file=\"snapshots/a&amp;b.vtu\"/>"};
  std::size_t previous = 0;
  for (const auto& line : expected) {
    const auto at = pvd.find(line);
    ASSERT_NE(at, std::string::npos) << line << "\n" << pvd;
    EXPECT_GT(at, previous);
    previous = at;
  }
  EXPECT_EQ(files_in_dir(), std::vector<fs::path>{"snapshots.pvd"});

  EXPECT_THROW(series.add(std::numeric_limits<double>::quiet_NaN(), "x.vtu"),
               std::invalid_argument);
  EXPECT_EQ(series.entries().size(), 3u);
}

}  // namespace
}  // namespace flume::io
