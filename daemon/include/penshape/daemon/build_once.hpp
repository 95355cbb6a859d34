#pragma once
// A value built once, by whichever thread asks first: a helper job started early on another
// worker, or the owner when it needs the value. The owner never waits for a helper that has not
// started (it builds the value itself); it waits only for one already building. Used to build a
// live stroke's ink polygon while the recognizer fits the stroke's path.
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <utility>

namespace penshape::daemon {

template <typename T>
class BuildOnce {
 public:
  explicit BuildOnce(std::function<T()> build) : build_(std::move(build)) {}
  BuildOnce(const BuildOnce&) = delete;
  BuildOnce& operator=(const BuildOnce&) = delete;

  // The value: built here unless it is built or being built elsewhere, then waited for. Rethrows
  // what the build threw (to every caller).
  T& get() {
    std::unique_lock lock(mutex_);
    if (state_ == State::kWaiting) build_here(lock);
    done_.wait(lock, [this] { return state_ == State::kBuilt; });
    if (error_) std::rethrow_exception(error_);
    return *value_;
  }

  // Whether the value (or its error) is there: get() would not wait or build.
  bool built() {
    std::lock_guard lock(mutex_);
    return state_ == State::kBuilt;
  }
  // The helper's side: builds the value unless somebody has started; never waits.
  void build_if_not_started() {
    std::unique_lock lock(mutex_);
    if (state_ == State::kWaiting) build_here(lock);
  }

 private:
  enum class State { kWaiting, kBuilding, kBuilt };

  // Called with the lock held and state kWaiting; builds without the lock.
  void build_here(std::unique_lock<std::mutex>& lock) {
    state_ = State::kBuilding;
    lock.unlock();
    std::optional<T> value;
    std::exception_ptr error;
    try {
      value.emplace(build_());
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    value_ = std::move(value);
    error_ = error;
    state_ = State::kBuilt;
    build_ = nullptr; // what it captured is no longer needed
    done_.notify_all();
  }

  std::mutex mutex_;
  std::condition_variable done_;
  State state_ = State::kWaiting;
  std::function<T()> build_;
  std::optional<T> value_;
  std::exception_ptr error_;
};

} // namespace penshape::daemon
