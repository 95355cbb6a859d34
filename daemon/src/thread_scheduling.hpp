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

// Asks the scheduler for a short time slice (0.1 ms) for the calling thread, once per thread:
// with Linux's EEVDF scheduler (6.6 and later; custom slices since 6.12) a thread with a short
// slice gets an earlier deadline and, on wake-up, preempts threads running with the default
// slice (stroke analyses, other programs' builds), without any privilege and without a bigger
// share of the CPU. For the threads a sample crosses on its way to a subscriber: the tablet
// reader and the gRPC thread writing the subscriber's stream. Older kernels ignore it.
void request_short_slice_once();

} // namespace penshape::daemon
