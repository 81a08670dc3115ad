// Running pieces of work in forked child processes: `flume bench` runs each configuration in
// its own child so that the child's peak resident memory (from wait4) is that run's alone, and
// so that runs cannot affect each other (heap growth, a crash, a blow-up); `flume validate
// --jobs N` runs N cases at once, each in its own child.
//
// The caller must not have started OpenMP threads (entered a parallel region) before forking:
// the child inherits the runtime's bookkeeping but not its threads, and GCC's libgomp can then
// hang in the child's first parallel region. The parents of bench and validate only read case
// files.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace flume {

struct ChildResult {
  bool exited = false;      // the child returned from `body` and exited normally
  int exit_code = -1;       // its exit status when `exited`
  int signal = 0;           // the signal that killed it otherwise (e.g. 9: out of memory)
  std::string output;       // what `body` returned, sent back through a pipe
  long peak_rss_bytes = 0;  // the child's peak resident set size (rusage.ru_maxrss)
};

// Forks; the child runs `body`, writes its return value to a pipe and exits with status 0 (1
// if `body` throws, whose message is then the output). The parent reads the pipe to its end,
// reaps the child with wait4 and returns what it got. Throws std::runtime_error if the pipe or
// the fork cannot be created.
ChildResult run_in_child(const std::function<std::string()>& body);

// How a child that did not exit with status 0 ended: "exit status N", or "killed by signal N
// (name)", with ", out of memory?" for SIGKILL (what the kernel's OOM killer sends).
std::string how_it_ended(const ChildResult& child);

// Each body in a child of its own as run_in_child, up to `jobs` children at a time (started in
// order, each as soon as one before it ends); the results in the order of the bodies.
std::vector<ChildResult> run_in_children(const std::vector<std::function<std::string()>>& bodies,
                                         int jobs);

}  // namespace flume
