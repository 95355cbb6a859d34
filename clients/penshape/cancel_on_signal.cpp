#include "cancel_on_signal.hpp"

#include <pthread.h>

namespace penshape::cli {

// SIGUSR2 is this object's own wake-up call for the waiter when the stream ended by itself.
CancelOnSignal::CancelOnSignal() {
  sigemptyset(&signals_);
  sigaddset(&signals_, SIGINT);
  sigaddset(&signals_, SIGTERM);
  sigaddset(&signals_, SIGUSR2);
  pthread_sigmask(SIG_BLOCK, &signals_, &previous_);
}

CancelOnSignal::Armed CancelOnSignal::arm(grpc::ClientContext* context) {
  {
    std::lock_guard lock(mutex_);
    context_ = context;
  }
  if (!waiter_.joinable()) {
    waiter_ = std::thread([this] {
      int sig = 0;
      sigwait(&signals_, &sig);
      if (sig != SIGUSR2) {
        fired_ = true;
        std::lock_guard lock(mutex_);
        if (context_ != nullptr) context_->TryCancel();
      }
    });
  }
  return Armed(*this);
}

void CancelOnSignal::disarm() {
  std::lock_guard lock(mutex_); // waits for a TryCancel in progress
  context_ = nullptr;
}

CancelOnSignal::~CancelOnSignal() {
  if (waiter_.joinable()) {
    pthread_kill(waiter_.native_handle(), SIGUSR2);
    waiter_.join();
  }
  pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
}

} // namespace penshape::cli
