// The two kinds of failure a user sees, each with its own exit status (spec/contract.md):
// InputError (exit 2): the case file or command line is wrong; SimulationError (exit 1): the
// simulation itself failed (NaN, blow-up, particle lost).
#pragma once

#include <stdexcept>
#include <string>

namespace flume {

// The message is one line (spec/contract.md): control characters of the user's text that it
// quotes (a TOML error citing a line break, a quoted key holding one) are written as escapes.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& what) : std::runtime_error(one_line(what)) {}

 private:
  static std::string one_line(const std::string& s) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    for (const char ch : s) {
      const auto c = static_cast<unsigned char>(ch);
      if (c == '\n') {
        out += "\\n";
      } else if (c == '\r') {
        out += "\\r";
      } else if (c == '\t') {
        out += "\\t";
      } else if (c < 0x20 || c == 0x7f) {
        out += "\\x";
        out += kHex[c >> 4];
        out += kHex[c & 15];
      } else {
        out += ch;
      }
    }
    return out;
  }
};

class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace flume
