// SIGINT and SIGTERM (run/interrupts.hpp): the first is noted for the run loop, which ends after
// the step in progress with a checkpoint (tests/regression/test_resume.cpp); a second SIGINT ends
// the process at once with exit 130. In a child process (gtest's death tests), so that the
// signals reach only it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>

#include "flume/run/interrupts.hpp"

namespace flume {
namespace {

TEST(InterruptHandlers, TheFirstSignalIsNotedTheSecondSigintExitsAtOnce) {
  EXPECT_EXIT(
      {
        const InterruptHandlers handlers;
        if (InterruptHandlers::pending() != 0) _exit(1);
        std::raise(SIGINT);
        if (InterruptHandlers::pending() != SIGINT) _exit(2);  // noted, still running
        std::raise(SIGINT);
        _exit(3);  // not reached: the second SIGINT exits with 130
      },
      ::testing::ExitedWithCode(130), "");
  EXPECT_EXIT(
      {
        const InterruptHandlers handlers;
        std::raise(SIGTERM);
        _exit(InterruptHandlers::pending() == SIGTERM ? 4 : 5);
      },
      ::testing::ExitedWithCode(4), "");
}

TEST(InterruptHandlers, ThePreviousHandlersComeBack) {
  EXPECT_EXIT(
      {
        { const InterruptHandlers handlers; }
        std::raise(SIGTERM);  // the default action again: the process is killed by it
        _exit(0);
      },
      ::testing::KilledBySignal(SIGTERM), "");
}

}  // namespace
}  // namespace flume
