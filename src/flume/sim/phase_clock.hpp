// Wall-clock seconds spent in each phase of a step (neighbour search, each sweep, integration,
// boundaries, checks, output), summed over steps: what `flume bench` reports as `phases`. A
// phase is named by a string literal; the list keeps the order in which phases first ran.
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace flume {

class PhaseClock {
 public:
  using Clock = std::chrono::steady_clock;

  void add(const char* phase, double seconds) {
    for (auto& [name, total] : totals_)
      if (name == phase) {
        total += seconds;
        return;
      }
    totals_.emplace_back(phase, seconds);
  }
  const std::vector<std::pair<std::string, double>>& totals() const { return totals_; }
  void reset() { totals_.clear(); }

  // Times the rest of the enclosing scope as `phase`.
  class Scope {
   public:
    Scope(PhaseClock* clock, const char* phase)
        : clock_(clock), phase_(phase), start_(Clock::now()) {}
    ~Scope() {
      if (clock_) clock_->add(phase_, std::chrono::duration<double>(Clock::now() - start_).count());
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    PhaseClock* clock_;
    const char* phase_;
    Clock::time_point start_;
  };

 private:
  std::vector<std::pair<std::string, double>> totals_;
};

}  // namespace flume
