#include "thread_scheduling.hpp"

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#endif

namespace penshape::daemon {

#if defined(__linux__)
namespace {

// The kernel's struct sched_attr (include/uapi/linux/sched/types.h); glibc has no wrapper and
// the uapi header clashes with <sched.h>.
struct SchedAttr {
  std::uint32_t size;
  std::uint32_t sched_policy;
  std::uint64_t sched_flags;
  std::int32_t sched_nice;
  std::uint32_t sched_priority;
  std::uint64_t sched_runtime; // SCHED_OTHER: the requested slice, in [100 µs, 100 ms]
  std::uint64_t sched_deadline;
  std::uint64_t sched_period;
};

constexpr std::uint64_t kShortestSliceNs = 100'000;

} // namespace

void lower_current_thread(int nice_increment, bool short_slice) {
  const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
  const int nice = std::min(::getpriority(PRIO_PROCESS, tid) + nice_increment, 19);
  if (short_slice) {
    SchedAttr attr{};
    attr.size = sizeof(attr);
    attr.sched_policy = SCHED_OTHER;
    attr.sched_nice = nice;
    attr.sched_runtime = kShortestSliceNs;
    if (::syscall(SYS_sched_setattr, 0, &attr, 0U) == 0) return;
  }
  (void)::setpriority(PRIO_PROCESS, tid, nice);
}

void make_current_thread_idle() {
  sched_param param{};
  param.sched_priority = 0;
  (void)::pthread_setschedparam(::pthread_self(), SCHED_IDLE, &param);
}

#else

void lower_current_thread(int /*nice_increment*/, bool /*short_slice*/) {}
void make_current_thread_idle() {}

#endif

} // namespace penshape::daemon
