#include "thread_scheduling.hpp"

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#endif

namespace penshape::daemon {

#if defined(__linux__)

void lower_current_thread(int nice_increment) {
  // Linux keeps niceness per thread: PRIO_PROCESS with a thread id changes only that thread.
  const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
  (void)::setpriority(PRIO_PROCESS, tid,
                      std::min(::getpriority(PRIO_PROCESS, tid) + nice_increment, 19));
}

void make_current_thread_idle() {
  sched_param param{};
  param.sched_priority = 0;
  (void)::pthread_setschedparam(::pthread_self(), SCHED_IDLE, &param);
}

#else

void lower_current_thread(int /*nice_increment*/) {}
void make_current_thread_idle() {}

#endif

} // namespace penshape::daemon
