#pragma once
// The daemon's SampleSink: device events and samples go straight to the hub (the reader thread
// only copies and queues); finished strokes go to the worker pool for their ink polygon and shape,
// then to the hub.
#include <condition_variable>
#include <mutex>

#include "daemon_state.hpp"

namespace penshape::daemon {

class Pipeline final : public SampleSink {
 public:
  explicit Pipeline(DaemonState& state) : state_(state) {}

  void device_attached(const DeviceDescriptor& device) override;
  void device_detached(const std::string& device_id) override;
  void stroke_started(const std::string& device_id, std::uint64_t stroke_id) override;
  void sample(const std::string& device_id, std::uint64_t stroke_id,
              const PenSample& sample) override;
  void stroke_finished(const std::string& device_id, Stroke stroke) override;

  // Returns once every finished stroke handed to the workers has been published.
  void wait_idle();

 private:
  void job_done();

  DaemonState& state_;
  std::mutex mutex_;
  std::condition_variable idle_;
  std::size_t in_flight_ = 0;
};

} // namespace penshape::daemon
