// Q built while the pen is down (InkAhead, the pipeline's work ahead): a stroke's pen-up Q is the
// one-shot ink_polygon() bit for bit whether its chunks were built ahead, cut short by a
// cancellation, or built under other pen settings; the pipeline asks for work ahead as samples
// arrive and the session's pen-up reuses it.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <thread>

#include "daemon_state.hpp"
#include "ink_ahead.hpp"
#include "penshape/core/ink.hpp"
#include "penshape/daemon/ink_analyzer.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"
#include "pipeline.hpp"

namespace {

namespace d = penshape::daemon;
namespace v1 = penshape::v1;
using namespace std::chrono_literals;

// A spiral of `n` samples at 1 kHz on a tablet of 100 units per mm.
penshape::Stroke spiral(std::uint64_t id, int n) {
  penshape::Stroke s;
  s.id = id;
  s.tablet.x_resolution = 100;
  s.tablet.y_resolution = 100;
  s.tablet.x_max = 100000;
  s.tablet.y_max = 100000;
  for (int i = 0; i < n; ++i) {
    const double a = 6 * std::numbers::pi * i / n;
    const double r = 5 + 10.0 * i / n;
    penshape::PenSample p;
    p.x = static_cast<std::int32_t>(std::lround((50 + r * std::cos(a)) * 100));
    p.y = static_cast<std::int32_t>(std::lround((50 + r * std::sin(a)) * 100));
    p.time_us = std::int64_t{i} * 1000;
    p.tip = true;
    p.in_range = true;
    s.samples.push_back(p);
  }
  return s;
}

penshape::Stroke prefix(const penshape::Stroke& s, std::size_t n) {
  penshape::Stroke out = s;
  out.samples.resize(n);
  return out;
}

std::string proto_of(const penshape::InkPolygon& q) {
  v1::PolygonSet out;
  d::to_proto(q.region, &out);
  return out.SerializeAsString() + std::to_string(q.hausdorff_bound);
}

std::string one_shot(const penshape::Stroke& s, const penshape::InkOptions& options) {
  return proto_of(penshape::ink_polygon(s, options));
}

TEST(InkAhead, FedAsDrawnGivesTheOneShotQ) {
  const penshape::Stroke s = spiral(1, 700);
  const penshape::InkOptions options = d::ink_options_for(d::PenSettings{});
  d::InkAhead ahead(options);
  for (std::size_t n = 50; n < s.samples.size(); n += 50) ahead.feed(prefix(s, n), {});
  EXPECT_EQ(ahead.built_chunks(), 650 / penshape::kInkChunkSegments);
  EXPECT_EQ(proto_of(ahead.polygon(penshape::ink_samples(s, options), options)),
            one_shot(s, options));
}

// A stroke that ends while its prefix Q is being built: the work stops between chunks, and the
// pen-up builds the rest.
TEST(InkAhead, CancelledWhileBuildingThePrefix) {
  const penshape::Stroke s = spiral(2, 400);
  const penshape::InkOptions options = d::ink_options_for(d::PenSettings{});
  d::InkAhead ahead(options);
  int asked = 0;
  ahead.feed(prefix(s, 390), [&asked] { return ++asked > 1; }); // cancelled after one chunk
  EXPECT_EQ(ahead.built_chunks(), 1U);
  EXPECT_EQ(proto_of(ahead.polygon(penshape::ink_samples(s, options), options)),
            one_shot(s, options));
}

// The pen's settings changed while the stroke was drawn: Q is drawn with the settings of the
// pen-up, none of the work ahead is used.
TEST(InkAhead, OtherOptionsAtPenUp) {
  const penshape::Stroke s = spiral(3, 300);
  d::PenSettings before;
  d::PenSettings after;
  after.pen_radius_mm = 2 * before.pen_radius_mm;
  d::InkAhead ahead(d::ink_options_for(before));
  ahead.feed(s, {});
  const penshape::InkOptions options = d::ink_options_for(after);
  EXPECT_EQ(proto_of(ahead.polygon(penshape::ink_samples(s, options), options)),
            one_shot(s, options));
}

// Counts the work ahead the pipeline asks for; the rest is the recognizing analyzer's.
class CountingAnalyzer final : public d::StrokeAnalyzer {
 public:
  d::StrokeAnalysis analyze(const penshape::Stroke& stroke, const d::PenSettings& settings,
                            const penshape::CancelHook& cancel) override {
    return inner_->analyze(stroke, settings, cancel);
  }
  std::unique_ptr<d::StrokeGroupSession> group_session(
      const d::PenSettings& settings, const penshape::GroupingConfig& grouping) override {
    return inner_->group_session(settings, grouping);
  }
  void work_ahead(const penshape::Stroke& partial, const d::PenSettings& settings,
                  const penshape::CancelHook& cancel) override {
    ++calls;
    inner_->work_ahead(partial, settings, cancel);
  }
  std::atomic<int> calls{0};

 private:
  std::shared_ptr<d::StrokeAnalyzer> inner_ = d::make_recognizing_analyzer();
};

TEST(InkAhead, PipelineWorksAheadWhileThePenIsDown) {
  auto analyzer = std::make_shared<CountingAnalyzer>();
  d::DaemonState state{d::Limits{}, d::PenSettings{}, {}};
  state.analyzer = analyzer;
  d::Pipeline pipeline(state);
  const penshape::Stroke s = spiral(7, 500);
  pipeline.stroke_started("tablet", s.id);
  for (const penshape::PenSample& p : s.samples) {
    pipeline.sample("tablet", s.id, p);
    std::this_thread::sleep_for(50us); // the worker keeps up, as at a tablet's pace
  }
  pipeline.stroke_finished("tablet", s);
  pipeline.wait_idle();
  EXPECT_GE(analyzer->calls.load(), 1); // one per 64 samples while none runs
  EXPECT_LE(analyzer->calls.load(), 500 / static_cast<int>(penshape::kInkChunkSegments));
}

} // namespace
