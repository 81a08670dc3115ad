// Atomic whole-file writes via write-to-temporary-then-rename (see atomic_file.hpp).
#include "flume/io/atomic_file.hpp"

#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <fmt/format.h>

namespace flume::io {

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  // The temporary must live in the same directory: rename is only atomic within one file
  // system. The pid keeps concurrent runs writing into the same directory apart.
  std::filesystem::path tmp = path;
  tmp += fmt::format(".tmp-{}", static_cast<long>(::getpid()));

  auto fail = [&](std::string_view what) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path.string(), what));
  };

  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) fail(fmt::format("cannot open temporary file '{}'", tmp.string()));
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    out.close();
    // close() sets failbit if the final flush fails (e.g. disk full), so this catches errors
    // that happened anywhere along the way.
    if (!out) fail(fmt::format("error while writing temporary file '{}'", tmp.string()));
  }

  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) fail(fmt::format("cannot rename '{}' over it: {}", tmp.string(), ec.message()));
}

}  // namespace flume::io
