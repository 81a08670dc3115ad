// A small RAII layer over the HDF5 C library (Debian libhdf5-dev) for the checkpoints: files,
// groups, attributes and contiguous datasets of doubles, 64-bit integers and strings. Every
// failure throws std::runtime_error naming the file and the object; HDF5's own error stack
// printing is switched off (a damaged checkpoint is an expected event, reported in one line).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace flume::io {

class Hdf5File {
 public:
  // Creates (truncating) or opens read-only.
  static Hdf5File create(const std::filesystem::path& path);
  static Hdf5File open_read(const std::filesystem::path& path);
  Hdf5File(Hdf5File&& other) noexcept;
  Hdf5File& operator=(Hdf5File&&) = delete;
  Hdf5File(const Hdf5File&) = delete;
  ~Hdf5File();
  // Closes the file, throwing if HDF5 cannot finish writing it.
  void close();

  // A group (absolute path, e.g. "/particles"); parents must exist.
  void create_group(const std::string& group);
  bool exists(const std::string& object) const;

  // Attributes on an object ("/" for the file).
  void set_attribute(const std::string& object, const std::string& name, double value);
  void set_attribute(const std::string& object, const std::string& name, std::int64_t value);
  void set_attribute(const std::string& object, const std::string& name, std::uint64_t value);
  void set_attribute(const std::string& object, const std::string& name, const std::string& value);
  double attribute_double(const std::string& object, const std::string& name) const;
  std::int64_t attribute_int(const std::string& object, const std::string& name) const;
  std::uint64_t attribute_uint(const std::string& object, const std::string& name) const;
  std::string attribute_string(const std::string& object, const std::string& name) const;

  // Datasets with the given shape (the product of the dims is the data's size; no dims: a
  // scalar).
  void write(const std::string& dataset, const std::vector<std::size_t>& dims, const double* data);
  void write(const std::string& dataset, const std::vector<std::size_t>& dims,
             const std::int64_t* data);
  void write_string(const std::string& dataset, const std::string& value);
  std::vector<std::size_t> dims(const std::string& dataset) const;
  // Reads into data, which must hold the product of dims(dataset) values.
  void read(const std::string& dataset, double* data) const;
  void read(const std::string& dataset, std::int64_t* data) const;
  std::string read_string(const std::string& dataset) const;
  // The names of a group's members, in HDF5's (alphabetical) order.
  std::vector<std::string> members(const std::string& group) const;

  const std::filesystem::path& path() const { return path_; }

 private:
  Hdf5File(std::filesystem::path path, std::int64_t id) : path_(std::move(path)), id_(id) {}
  std::filesystem::path path_;
  std::int64_t id_ = -1;  // hid_t
};

}  // namespace flume::io
