#pragma once
// Test doubles for the daemon's pluggable parts: a sample source the test drives, a stroke
// analyzer with a trivially checkable answer, and a geometry backend that can be made slow.
#include <atomic>
#include <chrono>
#include <future>
#include <mutex>
#include <thread>
#include <vector>

#include "penshape/daemon/geometry_backend.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "penshape/daemon/sample_source.hpp"
#include "penshape/daemon/stroke_analyzer.hpp"

namespace penshape::testing {

inline TabletInfo test_tablet() {
  TabletInfo t;
  t.bus = Bus::kUsb;
  t.vendor_id = 0x056a;
  t.product_id = 0x0010;
  t.name = "Test Tablet";
  t.x_max = 20000;
  t.y_max = 15000;
  t.pressure_max = 1023;
  t.x_resolution = 100;
  t.y_resolution = 100;
  return t;
}

// Emits what a device manager would: attach, strokes (started, samples, finished), stop() finishing
// the stroke in progress.
class FakeSampleSource final : public daemon::SampleSource {
 public:
  void start(daemon::SampleSink& sink) override { sink_ = &sink; }
  void stop() override {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    stopped_ = true;
  }
  [[nodiscard]] std::vector<daemon::DeviceDescriptor> devices() const override {
    std::lock_guard lock(mutex_);
    return devices_;
  }

  void attach(const std::string& id) {
    daemon::DeviceDescriptor d{id, test_tablet(), "/dev/fake-" + id, false};
    {
      std::lock_guard lock(mutex_);
      devices_.push_back(d);
    }
    sink_->device_attached(d);
  }

  // One whole stroke of `samples` samples (the last has tip up), synchronously.
  void emit_stroke(const std::string& device, int samples,
                   std::chrono::microseconds interval = std::chrono::microseconds(0)) {
    Stroke stroke;
    stroke.id = ++next_id_;
    stroke.tablet = test_tablet();
    sink_->stroke_started(device, stroke.id);
    for (int i = 0; i < samples; ++i) {
      PenSample s;
      s.time_us = static_cast<std::int64_t>(stroke.id) * 1'000'000 + std::int64_t{i} * 1000;
      s.x = 1000 + 10 * i;
      s.y = 2000 + (i % 50);
      s.pressure = 500;
      s.in_range = true;
      s.tip = i + 1 < samples;
      sink_->sample(device, stroke.id, s);
      stroke.samples.push_back(s);
      if (interval.count() > 0) std::this_thread::sleep_for(interval);
    }
    sink_->stroke_finished(device, std::move(stroke));
    ++finished_;
  }

  // Strokes one after another on a thread until stop(), which lets the stroke in progress finish.
  void run(const std::string& device, int samples, std::chrono::microseconds interval) {
    thread_ = std::thread([this, device, samples, interval] {
      while (!stop_) emit_stroke(device, samples, interval);
    });
  }

  [[nodiscard]] std::uint64_t finished() const { return finished_; }
  [[nodiscard]] bool stopped() const { return stopped_; }

 private:
  daemon::SampleSink* sink_ = nullptr;
  mutable std::mutex mutex_;
  std::vector<daemon::DeviceDescriptor> devices_;
  std::atomic<std::uint64_t> next_id_{0};
  std::atomic<std::uint64_t> finished_{0};
  std::atomic<bool> stop_{false};
  std::atomic<bool> stopped_{false};
  std::thread thread_;
};

// Ink polygon: the samples' bounding box in mm, grown by the pen radius (a rectangle the test can
// compute independently); shape: a segment from the first to the last sample.
class BoundingBoxAnalyzer final : public daemon::StrokeAnalyzer {
 public:
  daemon::StrokeAnalysis analyze(const Stroke& stroke, const daemon::PenSettings& settings,
                                 const CancelHook& /*cancel*/) override {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const PenSample& s : stroke.samples) {
      x0 = std::min(x0, s.x / stroke.tablet.x_resolution);
      x1 = std::max(x1, s.x / stroke.tablet.x_resolution);
      y0 = std::min(y0, s.y / stroke.tablet.y_resolution);
      y1 = std::max(y1, s.y / stroke.tablet.y_resolution);
    }
    const double r = settings.pen_radius_mm;
    daemon::StrokeAnalysis analysis;
    auto* ring = analysis.ink_polygon.add_polygons()->mutable_outer();
    for (auto [x, y] :
         {std::pair{x0 - r, y0 - r}, {x1 + r, y0 - r}, {x1 + r, y1 + r}, {x0 - r, y1 + r}}) {
      auto* p = ring->add_points();
      p->set_x(x);
      p->set_y(y);
    }
    analysis.shape.set_kind(v1::SHAPE_KIND_SEGMENT);
    ++calls;
    return analysis;
  }
  // A circle whose confidence is the number of samples seen so far. With hold_previews, a
  // preview runs until it is cancelled (at most 20 s), like a slow fit that its stroke's end
  // makes useless.
  std::vector<v1::Shape> preview(const Stroke& partial, const daemon::PenSettings& /*settings*/,
                                 const CancelHook& cancel) override {
    if (late_previews) { // computed on, past the pen-up, until the test lets it return
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while (!release_previews && std::chrono::steady_clock::now() < give_up) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      ++previews_returned_late;
    } else if (hold_previews) {
      ++previews_started;
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while (!(cancel && cancel()) && std::chrono::steady_clock::now() < give_up) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      ++previews_cancelled;
      throw Cancelled();
    }
    v1::Shape circle;
    circle.set_kind(v1::SHAPE_KIND_CIRCLE);
    circle.set_confidence(static_cast<double>(partial.samples.size()));
    ++previews;
    return {circle};
  }
  std::atomic<int> previews{0};
  std::atomic<int> calls{0};
  std::atomic<bool> hold_previews{false};
  std::atomic<int> previews_started{0};
  std::atomic<int> previews_cancelled{0};
  // With late_previews, a preview ignores its cancel hook and returns its candidate once
  // release_previews is set (like a preview step that does not look at the hook).
  std::atomic<bool> late_previews{false};
  std::atomic<bool> release_previews{false};
  std::atomic<int> previews_returned_late{0};
};

// Deconstruct: with r <= eps answers YES with P = Q (the paper's trivial case); otherwise, when
// `slow`, loops until the CancelHook says stop, recording that it stopped.
class FakeGeometryBackend final : public daemon::GeometryBackend {
 public:
  DeconstructResult deconstruct(const PolygonSet& q, const DeconstructParams& params,
                                const CancelHook& cancel,
                                const DeconstructLimits& /*limits*/) override {
    DeconstructResult result;
    result.params = params;
    result.engine = params.engine;
    if (params.radius <= params.tolerance) {
      result.answer = Answer::kYes;
      result.solution = q;
      result.hausdorff_bound = params.radius;
      return result;
    }
    started.set_value();
    while (!cancel()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    stopped.set_value();
    throw Cancelled();
  }
  std::promise<void> started;
  std::promise<void> stopped;
};

} // namespace penshape::testing
