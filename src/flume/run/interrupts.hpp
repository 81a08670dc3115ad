// SIGINT and SIGTERM during a run: the first one is noted and the run ends after the step in
// progress, with a checkpoint and summary.json's status "interrupted" (runner.cpp); a second
// SIGINT ends the process at once (exit 130), for a user who does not want to wait.
#pragma once

namespace flume {

// Installs the handlers for its lifetime and puts the previous ones back after.
class InterruptHandlers {
 public:
  InterruptHandlers();
  ~InterruptHandlers();
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;

  // The signal received (SIGINT or SIGTERM), or 0.
  static int pending();
};

}  // namespace flume
