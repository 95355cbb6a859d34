#pragma once
// The tablet the daemon benchmarks play strokes on: a SampleSource that attaches one device
// ("bench") and plays samples into the pipeline at 1 kHz as a tablet's reader thread would; and
// the machine's own wake-up lateness, the floor of every delivery the benchmarks time.
#include <chrono>
#include <thread>
#include <utility>
#include <vector>

#include "penshape/daemon/sample_source.hpp"
#include "penshape/daemon/shape_hub.hpp"

namespace penshape::bench {

class BenchTablet : public daemon::SampleSource {
 public:
  explicit BenchTablet(TabletInfo tablet) : tablet_(std::move(tablet)) {}
  void start(daemon::SampleSink& sink) override {
    sink_ = &sink;
    daemon::DeviceDescriptor d;
    d.id = "bench";
    d.tablet = tablet_;
    sink.device_attached(d);
  }
  void stop() override {}
  [[nodiscard]] std::vector<daemon::DeviceDescriptor> devices() const override { return {}; }

  // Plays one stroke's samples, one per millisecond, each stamped with the time it is "read"
  // (monotonic µs); returns the pen-up time handed to the pipeline.
  std::int64_t play_samples(std::uint64_t id, const std::vector<PenSample>& samples) {
    Stroke out;
    out.id = id;
    out.tablet = tablet_;
    auto next = std::chrono::steady_clock::now();
    sink_->stroke_started("bench", id);
    for (PenSample s : samples) {
      std::this_thread::sleep_until(next);
      next += std::chrono::milliseconds(1);
      s.time_us = daemon::monotonic_us();
      sink_->sample("bench", id, s);
      out.samples.push_back(s);
    }
    const std::int64_t up = daemon::monotonic_us();
    sink_->stroke_finished("bench", std::move(out));
    return up;
  }

 protected:
  TabletInfo tablet_;
  daemon::SampleSink* sink_ = nullptr;
};

// The machine's own wake-up lateness: a thread sleeping to each millisecond for `n` ms, nothing
// else running; how late it wakes, in µs.
inline std::vector<double> wakeup_lateness_us(int n) {
  std::vector<double> late;
  auto next = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) {
    next += std::chrono::milliseconds(1);
    std::this_thread::sleep_until(next);
    late.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - next).count());
  }
  return late;
}

} // namespace penshape::bench
