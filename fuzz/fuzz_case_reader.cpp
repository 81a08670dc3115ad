// libFuzzer target over the case reader and the --set parser (issue "runs that survive", item
// 5). An input is a case file, optionally preceded by --set overrides, one per line:
//   --set KEY=VALUE
//   ...
//   <TOML text>
// Every input must either read (a CaseSpec) or be refused with an InputError whose message is
// one line starting with the file name; anything else (another exception, a crash, a sanitizer
// report, a multi-line message) is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "flume/case/case_reader.hpp"
#include "flume/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view in(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> sets;
  constexpr std::string_view kSet = "--set ";
  while (in.starts_with(kSet)) {
    const auto end = in.find('\n');
    sets.emplace_back(in.substr(
        kSet.size(), end == std::string_view::npos ? std::string_view::npos : end - kSet.size()));
    in = end == std::string_view::npos ? std::string_view{} : in.substr(end + 1);
  }
  try {
    (void)flume::read_case_string(std::string(in), "fuzz.toml", sets);
  } catch (const flume::InputError& e) {
    const std::string msg = e.what();
    if (msg.find('\n') != std::string::npos || msg.rfind("fuzz.toml", 0) != 0) {
      std::fprintf(stderr, "an InputError that is not one line naming the file: %s\n", msg.c_str());
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "an error that is not an InputError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
