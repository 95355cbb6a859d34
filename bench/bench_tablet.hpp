#pragma once
// The tablet the daemon benchmarks play strokes on: a SampleSource that attaches one device
// ("bench") with the given tablet and keeps the pipeline's sink for the player (the subclasses).
#include <utility>
#include <vector>

#include "penshape/daemon/sample_source.hpp"

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

 protected:
  TabletInfo tablet_;
  daemon::SampleSink* sink_ = nullptr;
};

} // namespace penshape::bench
