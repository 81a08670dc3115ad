// Atomic whole-file writes: the contract (spec/contract.md, "A run's directory") promises that a
// killed run never leaves a half-written file under a final name, so every output file goes
// through here.
#pragma once

#include <filesystem>
#include <string_view>

namespace flume::io {

// Writes `content` to `path` + ".tmp-<pid>" in the same directory, then renames it over `path`.
// Readers see either the old file or the complete new one, never a partial write. Throws
// std::runtime_error naming the file on any failure (the temporary is removed).
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

}  // namespace flume::io
