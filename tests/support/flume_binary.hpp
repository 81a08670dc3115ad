// Running the flume executable from a test, as a user does: each test gets a fresh folder
// (removed afterwards) and each run's exit status, stdout and stderr. FLUME_BINARY is the path
// of the executable, defined for the regression tests by tests/CMakeLists.txt.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace flume::test {

namespace fs = std::filesystem;

// A file's whole content, byte for byte.
inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct CliResult {
  int status = -1;  // the exit status, -1 if the process did not exit normally
  std::string out, err;
};

class FlumeBinaryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("flume_" + std::string(info->test_suite_name()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliResult flume(const std::string& args) { return flume_env("", args); }
  // `env` prefixes the command, e.g. "NAME=value ".
  CliResult flume_env(const std::string& env, const std::string& args) {
    const std::string cmd = env + std::string(FLUME_BINARY) + " " + args + " > " +
                            (dir_ / "stdout").string() + " 2> " + (dir_ / "stderr").string();
    const int raw = std::system(cmd.c_str());
    CliResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(dir_ / "stdout");
    r.err = slurp(dir_ / "stderr");
    return r;
  }

  fs::path dir_;
};

}  // namespace flume::test
