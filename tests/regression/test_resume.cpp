// Runs that survive (issue "runs that survive"): a run killed with SIGKILL at a random step and
// resumed from its newest checkpoint writes the same files, byte for byte, as the run that was
// never interrupted; likewise after SIGTERM (exit 143, status "interrupted") and SIGINT (130),
// with another thread count; a truncated newest checkpoint is named and the one before used.
// Byte for byte is the tolerance: the state of the checkpoint is the state of the run (every
// state field, the clock, leap-frog's history, the output counters), and flume's results do
// not depend on the thread count.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <random>
#include <thread>

#include "flume/io/csv_table.hpp"
#include "flume/run/checkpoint.hpp"
#include "support/flume_binary.hpp"
#include "support/small_cases.hpp"

extern char** environ;

namespace flume {
namespace {

using test::slurp;
namespace fs = std::filesystem;

// The small dam break (576 particles, about 900 steps, a fraction of a second) with a row
// every 0.002 s, a snapshot every 0.01 s and a checkpoint every 20 steps.
std::string resumable_case() {
  std::string toml = test::dam_break_toml("continuity", 24, 0.08);
  toml += R"(
[checkpoint]
every_steps = 20
keep = 3
)";
  const std::string from = "interval = 0.08\nsnapshot_interval = 0.0";
  toml.replace(toml.find(from), from.size(), "interval = 0.002\nsnapshot_interval = 0.01");
  return toml;
}

class Resume : public test::FlumeBinaryTest {
 protected:
  fs::path write_case() {
    const auto file = dir_ / "case.toml";
    std::ofstream(file) << resumable_case();
    return file;
  }
  // Starts `flume ARGS` with its output sent to files in the test folder.
  pid_t start(const std::vector<std::string>& args) {
    std::vector<std::string> argv{FLUME_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> cargv;
    for (auto& a : argv)
      cargv.push_back(a.data());
    cargv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, (dir_ / "bg.out").c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, (dir_ / "bg.err").c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = -1;
    EXPECT_EQ(posix_spawn(&pid, cargv[0], &fa, nullptr, cargv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&fa);
    return pid;
  }
  // The exit status, or 128 + the signal that ended the process.
  static int wait_for(pid_t pid) {
    int raw = 0;
    waitpid(pid, &raw, 0);
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  }
  // Waits until the run has a checkpoint at step >= step (or it has ended).
  static bool wait_for_checkpoint(const fs::path& run, long step, pid_t pid) {
    for (int k = 0; k < 60000; ++k) {
      const auto all = list_checkpoints(run);
      if (!all.empty() && std::stol(all.back().stem().string().substr(11)) >= step) return true;
      int raw = 0;
      if (waitpid(pid, &raw, WNOHANG) == pid) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }
  // The run that was never interrupted.
  fs::path reference(const fs::path& file) {
    const auto ref = dir_ / "reference";
    // On two threads at this size too (--particles-per-thread 0): the runs resumed on one
    // thread are compared with it.
    EXPECT_EQ(flume("run " + file.string() +
                    " --quiet --threads 2 --particles-per-thread 0 --out " + ref.string())
                  .status,
              0);
    return ref;
  }
  static void expect_same_outputs(const fs::path& a, const fs::path& b) {
    for (const char* f : {"diagnostics.csv", "probes.csv", "snapshots/snapshots.pvd"})
      EXPECT_EQ(slurp(a / f), slurp(b / f)) << f;
    const auto pvd = io::read_csv(a / "diagnostics.csv").rows.size();
    EXPECT_GT(pvd, 30u);
    // Every snapshot, the final one included.
    int n = 0;
    for (const auto& e : fs::directory_iterator(a / "snapshots"))
      if (e.path().extension() == ".vtu") {
        ++n;
        EXPECT_EQ(slurp(e.path()), slurp(b / "snapshots" / e.path().filename()))
            << e.path().filename();
      }
    EXPECT_GE(n, 9);
    const auto summary = nlohmann::json::parse(slurp(b / "summary.json"));
    EXPECT_EQ(summary["status"], "completed");
    EXPECT_EQ(summary["steps"], nlohmann::json::parse(slurp(a / "summary.json"))["steps"]);
  }
};

TEST_F(Resume, AfterSigkillAtARandomStepTheRunEndsAsIfNeverStopped) {
  const auto file = write_case();
  const auto ref = reference(file);
  const long steps = nlohmann::json::parse(slurp(ref / "summary.json"))["steps"];
  ASSERT_GT(steps, 200);
  // The kill comes after a random checkpoint (seeded by the clock, printed on failure), at
  // whatever step the run has then reached.
  const auto seed =
      static_cast<unsigned>(std::chrono::steady_clock::now().time_since_epoch().count());
  std::mt19937 rng(seed);
  // Before half-way: the run must still be going when the kill comes.
  const long at = 20 * std::uniform_int_distribution<long>(1, steps / 40)(rng);
  const auto run = dir_ / "killed";
  const pid_t pid =
      start({"run", file.string(), "--quiet", "--threads", "2", "--out", run.string()});
  ASSERT_TRUE(wait_for_checkpoint(run, at, pid)) << "seed " << seed;
  kill(pid, SIGKILL);
  EXPECT_EQ(wait_for(pid), 128 + SIGKILL);
  const auto r = flume("resume " + run.string() + " --quiet --threads 2");
  ASSERT_EQ(r.status, 0) << r.err << " seed " << seed;
  expect_same_outputs(ref, run);
  EXPECT_NE(slurp(run / "log.txt").find("resumed at step"), std::string::npos);
}

TEST_F(Resume, SigtermWritesACheckpointAndAnotherThreadCountResumesIt) {
  const auto file = write_case();
  const auto ref = reference(file);
  for (const int sig : {SIGTERM, SIGINT}) {
    const auto run = dir_ / (sig == SIGTERM ? "term" : "int");
    const pid_t pid = start({"run", file.string(), "--quiet", "--threads", "2",
                             "--particles-per-thread", "0", "--out", run.string()});
    ASSERT_TRUE(wait_for_checkpoint(run, 40, pid));
    kill(pid, sig);
    EXPECT_EQ(wait_for(pid), 128 + sig);
    const auto summary = nlohmann::json::parse(slurp(run / "summary.json"));
    EXPECT_EQ(summary["status"], "interrupted");
    EXPECT_NE(slurp(dir_ / "bg.err").find("flume resume"), std::string::npos);
    const auto r = flume("resume " + run.string() + " --quiet --threads 1");
    ASSERT_EQ(r.status, 0) << r.err;
    expect_same_outputs(ref, run);
  }
}

TEST_F(Resume, ATruncatedNewestCheckpointIsNamedAndThePreviousUsed) {
  const auto file = write_case();
  const auto ref = reference(file);
  const auto run = dir_ / "cut";
  const pid_t pid =
      start({"run", file.string(), "--quiet", "--threads", "2", "--out", run.string()});
  ASSERT_TRUE(wait_for_checkpoint(run, 100, pid));
  kill(pid, SIGKILL);
  wait_for(pid);
  const auto all = list_checkpoints(run);
  ASSERT_GE(all.size(), 2u);
  fs::resize_file(all.back(), fs::file_size(all.back()) / 2);
  const auto r = flume("resume " + run.string() + " --quiet --threads 2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find(all.back().filename().string() + " cannot be used"), std::string::npos)
      << r.err;
  EXPECT_NE(slurp(run / "log.txt").find("cannot be used"), std::string::npos);
  expect_same_outputs(ref, run);
}

TEST_F(Resume, NothingToResumeFromIsBadInput) {
  const auto file = write_case();
  const auto r0 = flume("resume " + (dir_ / "nowhere").string());
  EXPECT_EQ(r0.status, 2);
  EXPECT_NE(r0.err.find("not a run directory"), std::string::npos) << r0.err;
  const auto run = dir_ / "short";
  ASSERT_EQ(
      flume("run " + file.string() + " --quiet --set case.end_time=0.001 --out " + run.string())
          .status,
      0);
  const auto r = flume("resume " + run.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no checkpoint"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace flume
