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

// struct sched_attr (linux/sched/types.h), declared here: glibc wraps sched_setattr only since
// 2.41.
struct SchedAttr {
  std::uint32_t size = sizeof(SchedAttr);
  std::uint32_t sched_policy = SCHED_OTHER;
  std::uint64_t sched_flags = 0;
  std::int32_t sched_nice = 0;
  std::uint32_t sched_priority = 0;
  std::uint64_t sched_runtime = 0; // for SCHED_OTHER: the requested slice, nanoseconds
  std::uint64_t sched_deadline = 0;
  std::uint64_t sched_period = 0;
};

constexpr std::uint64_t kShortSliceNs = 100'000; // the kernel's minimum custom slice

} // namespace

void lower_current_thread(int nice_increment) {
  // Linux keeps niceness per thread: PRIO_PROCESS with a thread id changes only that thread.
  const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
  const int nice = std::min(::getpriority(PRIO_PROCESS, tid) + nice_increment, 19);
  (void)::setpriority(PRIO_PROCESS, tid, nice);
  // The default slice, even when created by a thread that asked for a short one (slices are
  // inherited): long computations must not preempt the readers.
  SchedAttr attr;
  attr.sched_nice = nice;
  (void)::syscall(SYS_sched_setattr, 0, &attr, 0U);
}

void make_current_thread_idle() {
  sched_param param{};
  param.sched_priority = 0;
  (void)::pthread_setschedparam(::pthread_self(), SCHED_IDLE, &param);
}

void request_short_slice_once() {
  thread_local bool done = false;
  if (done) return;
  done = true;
  const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
  if (::sched_getscheduler(0) != SCHED_OTHER) return; // only fair-class threads have slices
  SchedAttr attr;
  attr.sched_nice = ::getpriority(PRIO_PROCESS, tid); // keep the thread's niceness
  attr.sched_runtime = kShortSliceNs;
  (void)::syscall(SYS_sched_setattr, 0, &attr, 0U);
}

#else

void lower_current_thread(int /*nice_increment*/) {}
void make_current_thread_idle() {}
void request_short_slice_once() {}

#endif

} // namespace penshape::daemon
