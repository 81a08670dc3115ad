// run_in_children (run/child_process.hpp): each body in a forked child, a few at a time, the
// results in the order of the bodies, whatever order the children end in.
#include "flume/run/child_process.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace flume {
namespace {

TEST(ChildProcesses, ResultsInTheOrderOfTheBodies) {
  std::vector<std::function<std::string()>> bodies;
  for (int k = 0; k < 5; ++k)
    bodies.emplace_back([k] {
      ::usleep(static_cast<useconds_t>((5 - k) * 20000));  // the later ones end first
      return "body " + std::to_string(k);
    });
  const auto results = run_in_children(bodies, 3);
  ASSERT_EQ(results.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_TRUE(results[k].exited) << k;
    EXPECT_EQ(results[k].exit_code, 0) << k;
    EXPECT_EQ(results[k].output, "body " + std::to_string(k));
  }
}

// Two children at once, each writing 16 times a pipe's 64 KiB buffer: the parent must drain
// both pipes while they write, else each child blocks on its full pipe.
TEST(ChildProcesses, LongOutputsOfChildrenRunningAtOnce) {
  const std::size_t n = 16 * 65536;
  std::vector<std::function<std::string()>> bodies{[n] { return std::string(n, 'a'); },
                                                   [n] { return std::string(n + 1, 'b'); }};
  const auto results = run_in_children(bodies, 2);
  EXPECT_EQ(results[0].output, std::string(n, 'a'));
  EXPECT_EQ(results[1].output, std::string(n + 1, 'b'));
}

TEST(ChildProcesses, AThrowOrASignalIsThatChildsAlone) {
  std::vector<std::function<std::string()>> bodies{
      []() -> std::string { throw std::runtime_error("no such thing"); },
      []() -> std::string {
        ::raise(SIGKILL);
        return "never";
      },
      [] { return std::string("fine"); }};
  const auto results = run_in_children(bodies, 2);
  EXPECT_TRUE(results[0].exited);
  EXPECT_EQ(results[0].exit_code, 1);
  EXPECT_EQ(results[0].output, "no such thing");
  EXPECT_FALSE(results[1].exited);
  EXPECT_EQ(results[1].signal, SIGKILL);
  // What validate and bench report of them (glibc's name of signal 9 is "Killed").
  EXPECT_EQ(how_it_ended(results[0]), "exit status 1");
  EXPECT_EQ(how_it_ended(results[1]), "killed by signal 9 (Killed), out of memory?");
  EXPECT_EQ(results[2].output, "fine");
  EXPECT_EQ(results[2].exit_code, 0);
}

}  // namespace
}  // namespace flume
