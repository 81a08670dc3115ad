#include "flume/run/child_process.hpp"

#include <fmt/format.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <stdexcept>

namespace flume {

namespace {

// Writes all of `data` to fd, retrying partial writes and interrupted calls.
bool write_all(int fd, const std::string& data) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t w = ::write(fd, data.data() + done, data.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(w);
  }
  return true;
}

// The child's side: never returns into the caller's code, and leaves through _exit so that
// the parent's atexit handlers and stdio buffers are not run a second time.
[[noreturn]] void be_the_child(int fd, const std::function<std::string()>& body) {
  int status = 0;
  std::string out;
  try {
    out = body();
  } catch (const std::exception& e) {
    out = e.what();
    status = 1;
  } catch (...) {
    out = "unknown exception";
    status = 1;
  }
  if (!write_all(fd, out)) status = 1;
  ::close(fd);
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  ::_exit(status);
}

struct Running {
  pid_t pid = 0;
  int fd = -1;  // the read end of the child's pipe
  std::size_t index = 0;
};

Running start_child(const std::function<std::string()>& body, std::size_t index) {
  int fds[2];
  if (::pipe(fds) != 0)
    throw std::runtime_error(fmt::format("cannot create a pipe: {}", std::strerror(errno)));
  // Anything buffered would otherwise be written twice, once by each process.
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(fmt::format("cannot fork: {}", std::strerror(err)));
  }
  if (pid == 0) {
    ::close(fds[0]);
    be_the_child(fds[1], body);
  }
  ::close(fds[1]);
  return {pid, fds[0], index};
}

// Reaps the child whose pipe has closed.
void reap(pid_t pid, ChildResult& result) {
  int status = 0;
  struct rusage usage {};
  while (::wait4(pid, &status, 0, &usage) < 0)
    if (errno != EINTR)
      throw std::runtime_error(fmt::format("wait4 failed: {}", std::strerror(errno)));
  if (WIFEXITED(status)) {
    result.exited = true;
    result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
  }
  // Linux reports ru_maxrss in KiB.
  result.peak_rss_bytes = usage.ru_maxrss * 1024L;
}

}  // namespace

std::string how_it_ended(const ChildResult& child) {
  if (child.exited) return fmt::format("exit status {}", child.exit_code);
  return fmt::format("killed by signal {} ({}){}", child.signal, strsignal(child.signal),
                     child.signal == SIGKILL ? ", out of memory?" : "");
}

ChildResult run_in_child(const std::function<std::string()>& body) {
  return run_in_children({body}, 1).front();
}

std::vector<ChildResult> run_in_children(const std::vector<std::function<std::string()>>& bodies,
                                         int jobs) {
  std::vector<ChildResult> results(bodies.size());
  std::vector<Running> running;
  std::size_t next = 0;
  const auto limit = static_cast<std::size_t>(std::max(jobs, 1));
  while (next < bodies.size() || !running.empty()) {
    while (running.size() < limit && next < bodies.size()) {
      running.push_back(start_child(bodies[next], next));
      ++next;
    }
    // Every running child's pipe is drained as it fills (a child blocks on a full pipe).
    std::vector<pollfd> fds;
    for (const auto& r : running)
      fds.push_back({r.fd, POLLIN, 0});
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(fmt::format("poll failed: {}", std::strerror(errno)));
    }
    for (std::size_t k = fds.size(); k-- > 0;) {
      if (fds[k].revents == 0) continue;
      char buf[65536];
      const ssize_t r = ::read(running[k].fd, buf, sizeof buf);
      if (r < 0 && errno == EINTR) continue;
      if (r > 0) {
        results[running[k].index].output.append(buf, static_cast<std::size_t>(r));
        continue;
      }
      // End of the pipe (or an error reading it): the child has written everything.
      ::close(running[k].fd);
      reap(running[k].pid, results[running[k].index]);
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(k));
    }
  }
  return results;
}

}  // namespace flume
