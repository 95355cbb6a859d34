#pragma once
// Scheduling of the calling thread (Linux; no-ops elsewhere). Neither call needs a privilege:
// raising niceness and SCHED_IDLE are open to any process (and neither can be undone without one,
// which is why each lane has threads of its own). Failures are ignored: the thread then keeps the
// default scheduling, which is still correct, only less polite to the readers.
namespace penshape::daemon {

// Nice + `nice_increment`, capped at 19.
void lower_current_thread(int nice_increment);

// SCHED_IDLE: the thread runs only when a core has nothing else to do.
void make_current_thread_idle();

} // namespace penshape::daemon
