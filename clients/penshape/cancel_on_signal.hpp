#pragma once
// Ctrl-C (SIGINT) or SIGTERM cancels a streaming call, so `watch` and `record` end cleanly
// (files closed, exit code 0). Construct it before the first gRPC call: it blocks the signals in
// the calling thread, and threads created afterwards (gRPC's) inherit the mask, so only the
// waiter thread ever receives them.
#include <grpcpp/client_context.h>

#include <atomic>
#include <csignal>
#include <mutex>
#include <thread>

namespace penshape::cli {

class CancelOnSignal {
 public:
  CancelOnSignal();
  ~CancelOnSignal(); // stops the waiter and restores the signal mask
  CancelOnSignal(const CancelOnSignal&) = delete;
  CancelOnSignal& operator=(const CancelOnSignal&) = delete;

  // While it lives, a signal cancels the context it was armed with. Declare it after the context:
  // its destructor waits for a cancellation in progress, so the context is never used after it
  // is gone (a signal racing with the end of the stream).
  class Armed {
   public:
    explicit Armed(CancelOnSignal& owner) : owner_(&owner) {}
    ~Armed() { owner_->disarm(); }
    Armed(const Armed&) = delete;
    Armed& operator=(const Armed&) = delete;

   private:
    CancelOnSignal* owner_;
  };

  // From now on, while the returned guard lives, a signal cancels `context`.
  [[nodiscard]] Armed arm(grpc::ClientContext* context);
  [[nodiscard]] bool fired() const { return fired_.load(); }

 private:
  void disarm();

  sigset_t signals_{};
  sigset_t previous_{};
  std::atomic<bool> fired_{false};
  std::mutex mutex_;                       // guards context_ (held while cancelling it)
  grpc::ClientContext* context_ = nullptr; // armed with, until disarmed
  std::thread waiter_;
};

} // namespace penshape::cli
