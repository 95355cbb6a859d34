#pragma once
// Scheduling of the calling thread (Linux; no-ops elsewhere). Every call needs no privilege:
// raising niceness, asking for a shorter time slice and SCHED_IDLE are open to any process.
// Failures are ignored: the thread then keeps the default scheduling, which is still correct,
// only less responsive.
namespace penshape::daemon {

// Nice + `nice_increment` (capped at 19). With `short_slice`, also asks the scheduler for the
// shortest time slice (100 µs, sched_attr.sched_runtime; Linux >= 6.12 with EEVDF honours it):
// on EEVDF a running thread keeps its slice (about 3 ms by default) even against a higher
// priority thread that wakes up, so a long geometry computation would delay a tablet reader or
// a gRPC writer by milliseconds; with 100 µs slices it yields within 100 µs. Older kernels
// ignore the slice and rely on the niceness (CFS wake-up preemption).
void lower_current_thread(int nice_increment, bool short_slice);

// SCHED_IDLE: the thread runs only when a core has nothing else to do.
void make_current_thread_idle();

} // namespace penshape::daemon
