#include "flume/run/checkpoint.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string_view>
#include <system_error>

#include "flume/io/hdf5_file.hpp"

namespace flume {

namespace {

constexpr const char* kFormat = "flume checkpoint";
// 2: probe_state holds each probe's memory preceded by its length (run/case_probes.hpp); 1 held
// the semi-axes' two moments alone.
constexpr std::int64_t kFormatVersion = 2;
constexpr std::size_t kAnySize = std::numeric_limits<std::size_t>::max();

// 64-bit FNV-1a over the bytes of every value, in the order transfer() lists them.
class Checksum {
 public:
  void add(const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k) {
      h_ ^= b[k];
      h_ *= 1099511628211ull;
    }
  }
  void add(const std::string& s) {
    const std::uint64_t n = s.size();
    add(&n, sizeof n);
    add(s.data(), s.size());
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 14695981039346656037ull;
};

// How an array's elements are stored: as `Scalar`s, each element `dims` of them.
template <class T>
struct Element;
template <>
struct Element<double> {
  using Scalar = double;
  static std::vector<std::size_t> dims() { return {}; }
};
template <>
struct Element<std::int64_t> {
  using Scalar = std::int64_t;
  static std::vector<std::size_t> dims() { return {}; }
};
template <int D>
struct Element<Vec<D>> {
  using Scalar = double;
  static_assert(sizeof(Vec<D>) == D * sizeof(double));
  static std::vector<std::size_t> dims() { return {static_cast<std::size_t>(D)}; }
};

template <class T>
std::vector<std::size_t> array_dims(std::size_t n) {
  std::vector<std::size_t> dims{n};
  for (std::size_t d : Element<T>::dims())
    dims.push_back(d);
  return dims;
}

class Writer {
 public:
  explicit Writer(io::Hdf5File& f) : f_(f) {}
  void group(const std::string& path) { f_.create_group(path); }
  void group_attribute(const std::string& group, const std::string& name, std::int64_t& v) {
    f_.set_attribute(group, name, v);
    sum_.add(name);
    sum_.add(&v, sizeof v);
  }
  template <class T>
  void scalar(const std::string& path, const char* unit, T& v) {
    f_.write(path, {}, &v);
    f_.set_attribute(path, "unit", std::string(unit));
    sum_.add(path);
    sum_.add(&v, sizeof v);
  }
  void text(const std::string& path, std::string& s) {
    f_.write_string(path, s);
    sum_.add(path);
    sum_.add(s);
  }
  template <class T>
  void array(const std::string& path, const char* unit, std::vector<T>& a, std::size_t n) {
    if (n == kAnySize) n = a.size();
    using S = typename Element<T>::Scalar;
    f_.write(path, array_dims<T>(n), reinterpret_cast<const S*>(a.data()));
    f_.set_attribute(path, "unit", std::string(unit));
    sum_.add(path);
    sum_.add(a.data(), n * sizeof(T));
  }
  std::uint64_t checksum() const { return sum_.value(); }

 private:
  io::Hdf5File& f_;
  Checksum sum_;
};

class Reader {
 public:
  explicit Reader(const io::Hdf5File& f) : f_(f) {}
  void group(const std::string& path) {
    if (!f_.exists(path)) throw CheckpointError(fmt::format("has no group {}", path));
  }
  void group_attribute(const std::string& group, const std::string& name, std::int64_t& v) {
    v = f_.attribute_int(group, name);
    sum_.add(name);
    sum_.add(&v, sizeof v);
  }
  template <class T>
  void scalar(const std::string& path, const char*, T& v) {
    if (!f_.dims(path).empty()) throw CheckpointError(path + " is not a scalar");
    f_.read(path, &v);
    sum_.add(path);
    sum_.add(&v, sizeof v);
  }
  void text(const std::string& path, std::string& s) {
    s = f_.read_string(path);
    sum_.add(path);
    sum_.add(s);
  }
  template <class T>
  void array(const std::string& path, const char*, std::vector<T>& a, std::size_t n) {
    const auto dims = f_.dims(path);
    if (dims.empty() || (n != kAnySize && dims[0] != n) || dims != array_dims<T>(dims[0]))
      throw CheckpointError(fmt::format("{} has the wrong shape", path));
    a.resize(dims[0]);
    using S = typename Element<T>::Scalar;
    if (!a.empty()) f_.read(path, reinterpret_cast<S*>(a.data()));
    sum_.add(path);
    sum_.add(a.data(), a.size() * sizeof(T));
  }
  std::uint64_t checksum() const { return sum_.value(); }

 private:
  const io::Hdf5File& f_;
  Checksum sum_;
};

// The file's contents, in one list for the writer and the reader (and the checksum).
template <int D, class IO>
void transfer(IO& io, Checkpoint<D>& c) {
  io.text("/case_toml", c.case_toml);
  io.group("/state");
  io.scalar("/state/time", "s", c.state.time);
  io.scalar("/state/step", "-", c.state.steps);
  io.scalar("/state/last_dt", "s", c.state.last_dt);
  io.scalar("/state/first_dt", "s", c.state.first_dt);
  io.scalar("/state/leapfrog_dt_prev", "s", c.state.leapfrog_dt_prev);
  io.group("/output");
  io.scalar("/output/next_output", "-", c.output.next_output);
  io.scalar("/output/next_snapshot", "-", c.output.next_snapshot);
  io.scalar("/output/diagnostics_rows", "-", c.output.diagnostics_rows);
  io.scalar("/output/probe_rows", "-", c.output.probe_rows);
  io.array("/output/snapshot_times", "s", c.output.snapshot_times, kAnySize);
  io.array("/output/probe_state", "-", c.output.probe_state, kAnySize);
  io.group("/particles");
  auto& ps = c.particles;
  std::int64_t n = static_cast<std::int64_t>(ps.n_real), optional = ps.optional;
  io.group_attribute("/particles", "n_real", n);
  io.group_attribute("/particles", "optional_fields", optional);
  if (n <= 0 || optional < 0 || optional > static_cast<std::int64_t>(kFieldsAll))
    throw CheckpointError("has an impossible particle count or field set");
  ps.n_real = static_cast<std::size_t>(n);
  ps.optional = static_cast<unsigned>(optional);
  ps.for_each_named_state_field([&](const char* name, const char* unit, auto& field) {
    io.array(std::string("/particles/") + name, unit, field, ps.n_real);
  });
}

}  // namespace

std::filesystem::path checkpoint_path(const std::filesystem::path& run_dir, long step) {
  return run_dir / "checkpoints" / fmt::format("checkpoint_{:010d}.h5", step);
}

std::vector<std::filesystem::path> list_checkpoints(const std::filesystem::path& run_dir) {
  std::vector<std::pair<long long, std::filesystem::path>> found;
  std::error_code ec;
  const auto dir = run_dir / "checkpoints";
  if (!std::filesystem::is_directory(dir, ec)) return {};
  // checkpoint_<10 digits>.h5, as checkpoint_path writes them.
  const auto step_of = [](const std::string& file) -> long long {
    constexpr std::string_view kHead = "checkpoint_", kTail = ".h5";
    if (file.size() != kHead.size() + 10 + kTail.size() || !file.starts_with(kHead) ||
        !file.ends_with(kTail))
      return -1;
    const std::string digits = file.substr(kHead.size(), 10);
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return -1;
    return std::stoll(digits);
  };
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const long long step = step_of(entry.path().filename().string());
    if (step >= 0 && entry.is_regular_file(ec)) found.emplace_back(step, entry.path());
  }
  std::sort(found.begin(), found.end());
  std::vector<std::filesystem::path> paths;
  for (auto& [step, path] : found)
    paths.push_back(std::move(path));
  return paths;
}

void prune_checkpoints(const std::filesystem::path& run_dir, int keep) {
  auto all = list_checkpoints(run_dir);
  const std::size_t k = static_cast<std::size_t>(std::max(keep, 1));
  for (std::size_t i = 0; i + k < all.size(); ++i) {
    std::error_code ec;
    std::filesystem::remove(all[i], ec);
  }
}

template <int D>
void write_checkpoint(const std::filesystem::path& path, const Checkpoint<D>& c) {
  std::filesystem::create_directories(path.parent_path());
  const auto tmp = std::filesystem::path(path.string() + fmt::format(".tmp-{}", getpid()));
  try {
    auto f = io::Hdf5File::create(tmp);
    f.set_attribute("/", "format", std::string(kFormat));
    f.set_attribute("/", "format_version", kFormatVersion);
    f.set_attribute("/", "flume_version", std::string(FLUME_VERSION));
    f.set_attribute("/", "case_name", c.case_name);
    f.set_attribute("/", "dimension", static_cast<std::int64_t>(D));
    Writer w(f);
    // transfer() lists the contents for reading and writing alike; writing leaves them as
    // they are.
    transfer(w, const_cast<Checkpoint<D>&>(c));
    f.set_attribute("/", "checksum_fnv1a64", w.checksum());
    f.close();
    std::filesystem::rename(tmp, path);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
}

namespace {
io::Hdf5File open_checkpoint(const std::filesystem::path& path) {
  try {
    auto f = io::Hdf5File::open_read(path);
    if (f.attribute_string("/", "format") != kFormat)
      throw CheckpointError("is not a flume checkpoint");
    if (f.attribute_int("/", "format_version") != kFormatVersion)
      throw CheckpointError(fmt::format("has format version {}, this flume reads {}",
                                        f.attribute_int("/", "format_version"), kFormatVersion));
    return f;
  } catch (const CheckpointError&) {
    throw;
  } catch (const std::exception& e) {
    throw CheckpointError(e.what());
  }
}
}  // namespace

int checkpoint_dimension(const std::filesystem::path& path) {
  const auto f = open_checkpoint(path);
  try {
    return static_cast<int>(f.attribute_int("/", "dimension"));
  } catch (const std::exception& e) {
    throw CheckpointError(e.what());
  }
}

template <int D>
Checkpoint<D> read_checkpoint(const std::filesystem::path& path) {
  const auto f = open_checkpoint(path);
  Checkpoint<D> c;
  try {
    if (f.attribute_int("/", "dimension") != D)
      throw CheckpointError(fmt::format("is not a {}D checkpoint", D));
    c.case_name = f.attribute_string("/", "case_name");
    Reader r(f);
    transfer(r, c);
    if (r.checksum() != f.attribute_uint("/", "checksum_fnv1a64"))
      throw CheckpointError("fails its checksum (the file was changed or damaged)");
  } catch (const CheckpointError&) {
    throw;
  } catch (const std::exception& e) {
    throw CheckpointError(e.what());
  }
  return c;
}

template void write_checkpoint<2>(const std::filesystem::path&, const Checkpoint<2>&);
template void write_checkpoint<3>(const std::filesystem::path&, const Checkpoint<3>&);
template Checkpoint<2> read_checkpoint<2>(const std::filesystem::path&);
template Checkpoint<3> read_checkpoint<3>(const std::filesystem::path&);

}  // namespace flume
