#include "flume/io/hdf5_file.hpp"

#include <hdf5.h>

#include <stdexcept>
#include <type_traits>
#include <utility>

namespace flume::io {

static_assert(std::is_same_v<hid_t, std::int64_t>, "HDF5 1.10 or later: hid_t is 64-bit");

namespace {

// HDF5 prints its error stack to stderr by default; flume reports failures itself.
void quiet_hdf5() {
  static const bool once = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)once;
}

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw std::runtime_error(file.string() + ": HDF5 cannot " + what);
}

// An HDF5 identifier closed by its own close function when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)), close_(other.close_) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// Variable-length UTF-8 strings: h5py reads them back as str.
Handle string_type() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t.get(), H5T_VARIABLE);
  H5Tset_cset(t.get(), H5T_CSET_UTF8);
  return t;
}

Handle open_object(const std::filesystem::path& file, hid_t fid, const std::string& object) {
  Handle o(H5Oopen(fid, object.c_str(), H5P_DEFAULT), H5Oclose);
  if (!o.valid()) fail(file, "open " + object);
  return o;
}

template <class T>
void set_scalar_attribute(const std::filesystem::path& file, hid_t fid, const std::string& object,
                          const std::string& name, hid_t file_type, hid_t mem_type,
                          const T& value) {
  const Handle o = open_object(file, fid, object);
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const Handle a(
      H5Acreate2(o.get(), name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
  if (!a.valid() || H5Awrite(a.get(), mem_type, &value) < 0)
    fail(file, "write attribute " + name + " of " + object);
}

template <class T>
T scalar_attribute(const std::filesystem::path& file, hid_t fid, const std::string& object,
                   const std::string& name, hid_t mem_type) {
  const Handle o = open_object(file, fid, object);
  const Handle a(H5Aopen(o.get(), name.c_str(), H5P_DEFAULT), H5Aclose);
  T value{};
  if (!a.valid()) fail(file, "find attribute " + name + " of " + object);
  const Handle space(H5Aget_space(a.get()), H5Sclose);
  if (H5Sget_simple_extent_npoints(space.get()) != 1 || H5Aread(a.get(), mem_type, &value) < 0)
    fail(file, "read attribute " + name + " of " + object);
  return value;
}

void write_dataset(const std::filesystem::path& file, hid_t fid, const std::string& dataset,
                   const std::vector<std::size_t>& dims, hid_t file_type, hid_t mem_type,
                   const void* data) {
  std::vector<hsize_t> d(dims.begin(), dims.end());  // no dims: a scalar
  const Handle space(d.empty() ? H5Screate(H5S_SCALAR)
                               : H5Screate_simple(static_cast<int>(d.size()), d.data(), nullptr),
                     H5Sclose);
  const Handle set(H5Dcreate2(fid, dataset.c_str(), file_type, space.get(), H5P_DEFAULT,
                              H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose);
  if (!set.valid() || H5Dwrite(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail(file, "write dataset " + dataset);
}

void read_dataset(const std::filesystem::path& file, hid_t fid, const std::string& dataset,
                  hid_t mem_type, void* data) {
  const Handle set(H5Dopen2(fid, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid() || H5Dread(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail(file, "read dataset " + dataset);
}

}  // namespace

Hdf5File Hdf5File::create(const std::filesystem::path& path) {
  quiet_hdf5();
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) fail(path, "create the file");
  return Hdf5File(path, id);
}

Hdf5File Hdf5File::open_read(const std::filesystem::path& path) {
  quiet_hdf5();
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) fail(path, "open the file (not HDF5, or truncated)");
  return Hdf5File(path, id);
}

Hdf5File::Hdf5File(Hdf5File&& other) noexcept
    : path_(std::move(other.path_)), id_(std::exchange(other.id_, -1)) {}

Hdf5File::~Hdf5File() {
  if (id_ >= 0) H5Fclose(id_);
}

void Hdf5File::close() {
  const hid_t id = std::exchange(id_, -1);
  if (id >= 0 && H5Fclose(id) < 0) fail(path_, "finish writing the file");
}

void Hdf5File::create_group(const std::string& group) {
  const Handle g(H5Gcreate2(id_, group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!g.valid()) fail(path_, "create group " + group);
}

bool Hdf5File::exists(const std::string& object) const {
  if (object == "/") return true;
  return H5Lexists(id_, object.c_str(), H5P_DEFAULT) > 0;
}

void Hdf5File::set_attribute(const std::string& object, const std::string& name, double value) {
  set_scalar_attribute(path_, id_, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, value);
}
void Hdf5File::set_attribute(const std::string& object, const std::string& name,
                             std::int64_t value) {
  set_scalar_attribute(path_, id_, object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, value);
}
void Hdf5File::set_attribute(const std::string& object, const std::string& name,
                             std::uint64_t value) {
  set_scalar_attribute(path_, id_, object, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, value);
}
void Hdf5File::set_attribute(const std::string& object, const std::string& name,
                             const std::string& value) {
  const Handle type = string_type();
  const char* text = value.c_str();
  set_scalar_attribute(path_, id_, object, name, type.get(), type.get(), text);
}

double Hdf5File::attribute_double(const std::string& object, const std::string& name) const {
  return scalar_attribute<double>(path_, id_, object, name, H5T_NATIVE_DOUBLE);
}
std::int64_t Hdf5File::attribute_int(const std::string& object, const std::string& name) const {
  return scalar_attribute<std::int64_t>(path_, id_, object, name, H5T_NATIVE_INT64);
}
std::uint64_t Hdf5File::attribute_uint(const std::string& object, const std::string& name) const {
  return scalar_attribute<std::uint64_t>(path_, id_, object, name, H5T_NATIVE_UINT64);
}
std::string Hdf5File::attribute_string(const std::string& object, const std::string& name) const {
  const Handle type = string_type();
  char* text = scalar_attribute<char*>(path_, id_, object, name, type.get());
  if (text == nullptr) fail(path_, "read attribute " + name + " of " + object);
  std::string value(text);
  H5free_memory(text);
  return value;
}

void Hdf5File::write(const std::string& dataset, const std::vector<std::size_t>& dims,
                     const double* data) {
  write_dataset(path_, id_, dataset, dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data);
}
void Hdf5File::write(const std::string& dataset, const std::vector<std::size_t>& dims,
                     const std::int64_t* data) {
  write_dataset(path_, id_, dataset, dims, H5T_STD_I64LE, H5T_NATIVE_INT64, data);
}
void Hdf5File::write_string(const std::string& dataset, const std::string& value) {
  const Handle type = string_type();
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const Handle set(H5Dcreate2(id_, dataset.c_str(), type.get(), space.get(), H5P_DEFAULT,
                              H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose);
  const char* text = value.c_str();
  if (!set.valid() || H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, &text) < 0)
    fail(path_, "write dataset " + dataset);
}

std::vector<std::size_t> Hdf5File::dims(const std::string& dataset) const {
  const Handle set(H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) fail(path_, "find dataset " + dataset);
  const Handle space(H5Dget_space(set.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail(path_, "read the shape of " + dataset);
  std::vector<hsize_t> d(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), d.data(), nullptr);
  return {d.begin(), d.end()};
}

void Hdf5File::read(const std::string& dataset, double* data) const {
  read_dataset(path_, id_, dataset, H5T_NATIVE_DOUBLE, data);
}
void Hdf5File::read(const std::string& dataset, std::int64_t* data) const {
  read_dataset(path_, id_, dataset, H5T_NATIVE_INT64, data);
}
std::string Hdf5File::read_string(const std::string& dataset) const {
  const Handle type = string_type();
  char* text = nullptr;
  read_dataset(path_, id_, dataset, type.get(), &text);
  if (text == nullptr) fail(path_, "read dataset " + dataset);
  std::string value(text);
  H5free_memory(text);
  return value;
}

std::vector<std::string> Hdf5File::members(const std::string& group) const {
  const Handle g(H5Gopen2(id_, group.c_str(), H5P_DEFAULT), H5Gclose);
  if (!g.valid()) fail(path_, "open group " + group);
  H5G_info_t info;
  if (H5Gget_info(g.get(), &info) < 0) fail(path_, "list group " + group);
  std::vector<std::string> names;
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    const ssize_t len =
        H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
    if (len < 0) fail(path_, "list group " + group);
    std::string name(static_cast<std::size_t>(len), '\0');
    H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(),
                       static_cast<std::size_t>(len) + 1, H5P_DEFAULT);
    names.push_back(std::move(name));
  }
  return names;
}

}  // namespace flume::io
