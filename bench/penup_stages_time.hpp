#pragma once
// A step's thread CPU time beside its wall time, for penup_stages.hpp and its parts.
#include <time.h>

#include <chrono>
#include <vector>

namespace penshape::bench {

// This thread's CPU time, ms.
inline double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

// Thread CPU and wall time of one call, ms.
struct StepTime {
  std::vector<double> cpu_ms, wall_ms;
  template <typename F>
  void time(F&& f) {
    const double c0 = thread_cpu_ms();
    const auto w0 = std::chrono::steady_clock::now();
    f();
    wall_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count());
    cpu_ms.push_back(thread_cpu_ms() - c0);
  }
};

} // namespace penshape::bench
