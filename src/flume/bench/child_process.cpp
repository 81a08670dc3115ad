#include "flume/bench/child_process.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
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

}  // namespace

ChildResult run_in_child(const std::function<std::string()>& body) {
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
    // The child: never returns into the caller's code, and leaves through _exit so that the
    // parent's atexit handlers and stdio buffers are not run a second time.
    ::close(fds[0]);
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
    if (!write_all(fds[1], out)) status = 1;
    ::close(fds[1]);
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    ::_exit(status);
  }

  ::close(fds[1]);
  ChildResult result;
  char buf[4096];
  while (true) {
    const ssize_t r = ::read(fds[0], buf, sizeof buf);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    result.output.append(buf, static_cast<std::size_t>(r));
  }
  ::close(fds[0]);

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
  return result;
}

}  // namespace flume
