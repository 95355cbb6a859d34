#pragma once
// Ctrl-C (SIGINT) or SIGTERM cancels a streaming call, so `watch` and `record` end cleanly
// (files closed, exit code 0). Construct it before the first gRPC call: it blocks the signals in
// the calling thread, and threads created afterwards (gRPC's) inherit the mask, so only the
// waiter thread ever receives them.
#include <grpcpp/client_context.h>

#include <atomic>
#include <csignal>
#include <thread>

namespace penshape::cli {

class CancelOnSignal {
 public:
  CancelOnSignal();
  ~CancelOnSignal(); // stops the waiter and restores the signal mask
  CancelOnSignal(const CancelOnSignal&) = delete;
  CancelOnSignal& operator=(const CancelOnSignal&) = delete;

  // From now on a signal cancels `context` (which must outlive this object).
  void arm(grpc::ClientContext* context);
  [[nodiscard]] bool fired() const { return fired_.load(); }

 private:
  sigset_t signals_{};
  sigset_t previous_{};
  std::atomic<bool> fired_{false};
  std::thread waiter_;
};

} // namespace penshape::cli
