#include "flume/run/interrupts.hpp"

#include <unistd.h>

#include <csignal>

namespace flume {

namespace {

volatile std::sig_atomic_t g_signal = 0;
struct sigaction g_old_int, g_old_term;

extern "C" void on_signal(int sig) {
  // A second SIGINT: out now (only async-signal-safe calls here).
  if (g_signal != 0 && sig == SIGINT) _exit(128 + SIGINT);
  g_signal = sig;
}

}  // namespace

InterruptHandlers::InterruptHandlers() {
  g_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // a write in progress goes on instead of failing with EINTR
  sigaction(SIGINT, &sa, &g_old_int);
  sigaction(SIGTERM, &sa, &g_old_term);
}

InterruptHandlers::~InterruptHandlers() {
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
}

int InterruptHandlers::pending() {
  return g_signal;
}

}  // namespace flume
