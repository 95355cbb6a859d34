#pragma once
// A penshaped started by the test, in-process: the real server (Live, Config, Geometry services
// on a unix-abstract socket) with a sample source the test drives and, optionally, a stroke
// analyzer test double whose answer the test computes independently.
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "penshape/daemon/sample_source.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/daemon/stroke_analyzer.hpp"

namespace penshape::testing {

inline TabletInfo clients_test_tablet() {
  TabletInfo t;
  t.bus = Bus::kUsb;
  t.vendor_id = 0x056a;
  t.product_id = 0x0357;
  t.name = "Clients Test Tablet";
  t.x_max = 40000;
  t.y_max = 25000;
  t.pressure_max = 8191;
  t.x_resolution = 200; // units per mm: a 200 x 125 mm tablet
  t.y_resolution = 200;
  t.has_tilt = true;
  return t;
}

// Emits attach, strokes and detach when the test says so.
class ScriptedSource final : public daemon::SampleSource {
 public:
  void start(daemon::SampleSink& sink) override { sink_ = &sink; }
  void stop() override {}
  [[nodiscard]] std::vector<daemon::DeviceDescriptor> devices() const override {
    std::lock_guard lock(mutex_);
    return devices_;
  }
  void attach(const std::string& id) {
    daemon::DeviceDescriptor d{id, clients_test_tablet(), "/dev/test-" + id, false};
    {
      std::lock_guard lock(mutex_);
      devices_.push_back(d);
    }
    sink_->device_attached(d);
  }
  void detach(const std::string& id) {
    {
      std::lock_guard lock(mutex_);
      std::erase_if(devices_, [&](const auto& d) { return d.id == id; });
    }
    sink_->device_detached(id);
  }
  // Hover sample, the stroke (tip down), and a final tip-up sample; returns the stroke.
  Stroke draw(const std::string& device, const std::vector<PenSample>& tip_down) {
    Stroke stroke;
    stroke.id = ++next_id_;
    stroke.tablet = clients_test_tablet();
    PenSample hover = tip_down.front();
    hover.tip = false;
    hover.pressure = 0;
    hover.time_us -= 1000;
    sink_->sample(device, 0, hover);
    sink_->stroke_started(device, stroke.id);
    for (const PenSample& s : tip_down) {
      sink_->sample(device, stroke.id, s);
      stroke.samples.push_back(s);
    }
    PenSample up = tip_down.back();
    up.tip = false;
    up.pressure = 0;
    up.time_us += 1000;
    sink_->sample(device, stroke.id, up);
    stroke.samples.push_back(up);
    sink_->stroke_finished(device, stroke);
    return stroke;
  }

 private:
  daemon::SampleSink* sink_ = nullptr;
  mutable std::mutex mutex_;
  std::vector<daemon::DeviceDescriptor> devices_;
  std::atomic<std::uint64_t> next_id_{0};
};

// The tip-down samples' bounding box in mm.
struct BoxMm {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
};
inline BoxMm tip_box_mm(const Stroke& stroke) {
  BoxMm b;
  for (const PenSample& s : stroke.samples) {
    if (!s.tip) continue;
    const double x = s.x / stroke.tablet.x_resolution;
    const double y = s.y / stroke.tablet.y_resolution;
    b.x0 = std::min(b.x0, x);
    b.x1 = std::max(b.x1, x);
    b.y0 = std::min(b.y0, y);
    b.y1 = std::max(b.y1, y);
  }
  return b;
}

// Test double for the recognizer: every stroke "snaps" to the axis-parallel square centred on
// its bounding box with side = the mean of the box's width and height; the ink polygon is the
// box grown by the pen radius. Simple enough that a test predicts every number.
class SquareAnalyzer final : public daemon::StrokeAnalyzer {
 public:
  daemon::StrokeAnalysis analyze(const Stroke& stroke, const daemon::PenSettings& settings,
                                 const CancelHook& /*cancel*/) override {
    const BoxMm b = tip_box_mm(stroke);
    const double r = settings.pen_radius_mm;
    daemon::StrokeAnalysis a;
    auto* ring = a.ink_polygon.add_polygons()->mutable_outer();
    for (auto [x, y] : {std::pair{b.x0 - r, b.y0 - r},
                        {b.x1 + r, b.y0 - r},
                        {b.x1 + r, b.y1 + r},
                        {b.x0 - r, b.y1 + r}}) {
      auto* p = ring->add_points();
      p->set_x(x);
      p->set_y(y);
    }
    const double cx = (b.x0 + b.x1) / 2;
    const double cy = (b.y0 + b.y1) / 2;
    const double h = ((b.x1 - b.x0) + (b.y1 - b.y0)) / 4;
    a.shape.set_kind(v1::SHAPE_KIND_SQUARE);
    for (auto [x, y] :
         {std::pair{cx - h, cy - h}, {cx + h, cy - h}, {cx + h, cy + h}, {cx - h, cy + h}}) {
      auto* p = a.shape.mutable_vertices()->add_vertices();
      p->set_x(x);
      p->set_y(y);
    }
    a.shape.set_confidence(0.75);
    auto* cert = a.shape.mutable_certificate();
    cert->mutable_pen_radius()->set_approx(r);
    cert->mutable_pen_radius()->set_rational(std::to_string(r));
    const double eps = r * settings.tolerance_fraction;
    cert->mutable_tolerance()->set_approx(eps);
    cert->mutable_tolerance()->set_rational(std::to_string(eps));
    cert->mutable_hausdorff_bound()->set_approx(eps / 2);
    cert->mutable_hausdorff_bound()->set_rational(std::to_string(eps / 2));
    cert->set_method("test-double");
    ++calls;
    last_settings = settings;
    return a;
  }
  std::atomic<int> calls{0};
  daemon::PenSettings last_settings;
};

inline std::string unique_test_address(const std::string& tag) {
  static std::atomic<int> counter{0};
  return "unix-abstract:penshape-clients-" + tag + "-" + std::to_string(::getpid()) + "-" +
         std::to_string(++counter);
}

struct TestDaemon {
  explicit TestDaemon(const std::string& tag, bool with_analyzer = true,
                      std::shared_ptr<daemon::GeometryBackend> geometry = nullptr)
      : address(unique_test_address(tag)),
        source(std::make_shared<ScriptedSource>()),
        analyzer(with_analyzer ? std::make_shared<SquareAnalyzer>() : nullptr) {
    daemon::ServerOptions options;
    options.address = address;
    daemon::ServerParts parts;
    parts.source = source;
    parts.analyzer = analyzer;
    parts.geometry = std::move(geometry);
    server = std::make_unique<daemon::PenshapeServer>(options, parts);
  }
  std::string address;
  std::shared_ptr<ScriptedSource> source;
  std::shared_ptr<SquareAnalyzer> analyzer;
  std::unique_ptr<daemon::PenshapeServer> server;
};

// Tip-down samples from a $1 gesture: pixels scaled to device units (`units_per_pixel`) and
// shifted by `offset`, with the gesture's own times.
template <typename Points>
std::vector<PenSample> samples_from_points(const Points& points, double units_per_pixel,
                                           int offset_x, int offset_y) {
  std::vector<PenSample> out;
  const std::int64_t t0 = points.front().t_ms;
  for (const auto& p : points) {
    PenSample s;
    s.time_us = (p.t_ms - t0) * 1000 + 10'000;
    s.x = offset_x + static_cast<std::int32_t>(std::lround(p.x * units_per_pixel));
    s.y = offset_y + static_cast<std::int32_t>(std::lround(p.y * units_per_pixel));
    s.pressure = 4000;
    s.in_range = true;
    s.tip = true;
    if (!out.empty() && s.time_us < out.back().time_us) s.time_us = out.back().time_us;
    out.push_back(s);
  }
  return out;
}

} // namespace penshape::testing
