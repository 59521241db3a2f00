#pragma once
// Wall and CPU time of a pipeline stage (ms). CPU time is the whole
// process's (all threads), so on a shared machine it tells work from waiting.
#include <chrono>
#include <ctime>

namespace sketchlab::hermite_rbf {

class StageTimer {
 public:
  StageTimer() : wall_(std::chrono::steady_clock::now()), cpu_(cpu_now()) {}
  double wall_ms() const { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_).count(); }
  double cpu_ms() const { return cpu_now() - cpu_; }

 private:
  static double cpu_now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
  }
  std::chrono::steady_clock::time_point wall_;
  double cpu_;
};

}  // namespace sketchlab::hermite_rbf
