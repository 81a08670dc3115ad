// VTK XML writers for particle clouds (see vtk_writer.hpp).
#include "flume/io/vtk_writer.hpp"

#include <bit>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <unordered_set>

#include <fmt/format.h>

#include "flume/io/atomic_file.hpp"

namespace flume::io {

namespace {

// Field names and file names end up in XML attributes.
std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out.push_back(c);
    }
  }
  return out;
}

// Stores the low `bytes` bytes of `value` at `out`, little-endian. Written with shifts rather
// than memcpy so the file says LittleEndian truthfully on any host; compilers reduce this to a
// plain store on little-endian machines.
void store_le(char* out, std::uint64_t value, std::size_t bytes) {
  for (std::size_t i = 0; i < bytes; ++i) {
    out[i] = static_cast<char>(static_cast<unsigned char>(value >> (8 * i)));
  }
}

// Builds the appended-data block and the matching <DataArray> elements: each array's offset is
// its position after the '_' marker, and its payload is preceded by a UInt64 byte count.
class AppendedArrays {
 public:
  // Adds one array of `count` values of type T (VTK name `type`), get(i) giving the i-th value:
  // its <DataArray> line, indented by `indent`, goes to `xml` and its bytes to the block.
  template <typename T, typename Get>
  void add(std::string& xml, int indent, std::string_view type, std::string_view name,
           int components, std::size_t count, Get get) {
    fmt::format_to(std::back_inserter(xml),
                   "{:{}}<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
                   "format=\"appended\" offset=\"{}\"/>\n",
                   "", indent, type, xml_escape(name), components, data_.size());
    // Grow once and fill in place: snapshots can hold millions of values.
    const std::size_t bytes = count * sizeof(T);
    const std::size_t start = data_.size();
    data_.resize(start + 8 + bytes);
    char* out = data_.data() + start;
    store_le(out, static_cast<std::uint64_t>(bytes), 8);
    out += 8;
    for (std::size_t i = 0; i < count; ++i, out += sizeof(T)) {
      const T value = get(i);
      if constexpr (std::is_same_v<T, double>) {
        store_le(out, std::bit_cast<std::uint64_t>(value), sizeof(T));
      } else {
        store_le(out, static_cast<std::uint64_t>(value), sizeof(T));
      }
    }
  }

  const std::string& data() const { return data_; }

 private:
  std::string data_;
};

void check_cloud(const std::filesystem::path& path, const PointCloud& cloud) {
  auto bad = [&](std::string_view what) {
    throw std::invalid_argument(fmt::format("cannot write '{}': {}", path.string(), what));
  };
  if (cloud.xyz.size() % 3 != 0) bad("xyz size is not a multiple of 3");
  const std::size_t n = cloud.xyz.size() / 3;
  if (!cloud.ids.empty() && cloud.ids.size() != n) {
    bad(fmt::format("{} ids for {} points", cloud.ids.size(), n));
  }
  std::unordered_set<std::string_view> names;
  if (!cloud.ids.empty()) names.insert("id");
  for (const auto& field : cloud.fields) {
    if (field.name.empty()) bad("a field has an empty name");
    if (!names.insert(field.name).second) bad(fmt::format("duplicate field '{}'", field.name));
    if (field.components != 1 && field.components != 3) {
      bad(fmt::format("field '{}' has {} components (1 or 3 allowed)", field.name,
                      field.components));
    }
    if (field.data.size() != n * static_cast<std::size_t>(field.components)) {
      bad(fmt::format("field '{}' has {} values, expected {}", field.name, field.data.size(),
                      n * static_cast<std::size_t>(field.components)));
    }
  }
}

}  // namespace

void write_vtu(const std::filesystem::path& path, const PointCloud& cloud) {
  check_cloud(path, cloud);
  const std::size_t n = cloud.xyz.size() / 3;

  std::string xml;
  AppendedArrays arrays;
  xml += "<?xml version=\"1.0\"?>\n";
  xml +=
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n";
  xml += "  <UnstructuredGrid>\n";
  fmt::format_to(std::back_inserter(xml),
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n, n);

  xml += "      <Points>\n";
  arrays.add<double>(xml, 8, "Float64", "Points", 3, 3 * n,
                     [&](std::size_t i) { return cloud.xyz[i]; });
  xml += "      </Points>\n";

  // One vertex cell per point: ParaView needs cells to render points with most filters.
  xml += "      <Cells>\n";
  arrays.add<std::int64_t>(xml, 8, "Int64", "connectivity", 1, n,
                           [](std::size_t i) { return static_cast<std::int64_t>(i); });
  arrays.add<std::int64_t>(xml, 8, "Int64", "offsets", 1, n,
                           [](std::size_t i) { return static_cast<std::int64_t>(i + 1); });
  constexpr std::uint8_t kVtkVertex = 1;
  arrays.add<std::uint8_t>(xml, 8, "UInt8", "types", 1, n, [](std::size_t) { return kVtkVertex; });
  xml += "      </Cells>\n";

  xml += "      <PointData>\n";
  for (const auto& field : cloud.fields) {
    arrays.add<double>(xml, 8, "Float64", field.name, field.components, field.data.size(),
                       [&](std::size_t i) { return field.data[i]; });
  }
  if (!cloud.ids.empty()) {
    arrays.add<std::int64_t>(xml, 8, "Int64", "id", 1, n,
                             [&](std::size_t i) { return cloud.ids[i]; });
  }
  xml += "      </PointData>\n";

  xml += "    </Piece>\n";
  xml += "  </UnstructuredGrid>\n";
  xml += "  <AppendedData encoding=\"raw\">\n_";
  xml += arrays.data();
  xml += "\n  </AppendedData>\n";
  xml += "</VTKFile>\n";

  write_file_atomic(path, xml);
}

PvdSeries::PvdSeries(std::filesystem::path pvd_path) : pvd_path_(std::move(pvd_path)) {}

void PvdSeries::add(double time, const std::string& relative_file) {
  if (!std::isfinite(time)) {
    throw std::invalid_argument(fmt::format("'{}': snapshot time {} for '{}' is not finite",
                                            pvd_path_.string(), time, relative_file));
  }
  entries_.emplace_back(time, relative_file);

  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  xml += "  <Collection>\n";
  for (const auto& [t, file] : entries_) {
    fmt::format_to(std::back_inserter(xml),
                   "    <DataSet timestep=\"{:.17g}\" part=\"0\" file=\"{}\"/>\n", t,
                   xml_escape(file));
  }
  xml += "  </Collection>\n";
  xml += "</VTKFile>\n";
  try {
    write_file_atomic(pvd_path_, xml);
  } catch (...) {
    // Forget the entry too, so memory and disk keep listing the same files.
    entries_.pop_back();
    throw;
  }
}

}  // namespace flume::io
