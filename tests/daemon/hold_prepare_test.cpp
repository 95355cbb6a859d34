// Hold to snap recognized ahead (LiveGrouping::prepare_hold): once the pen has rested a quarter of
// hold_ms, the strand recognizes the stroke drawn before the rest, so that the hold publishes at
// once. These tests count the analyzer's add_held calls through a wrapping session: the prepared
// answer is used by the hold of the same rest (one recognition, the same shape as without it),
// and never after anything else changed the grouping or for another rest's stroke.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <thread>

#include "daemon_state.hpp"
#include "hold_state.hpp"
#include "live_grouping.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"

namespace {

namespace d = penshape::daemon;
namespace v1 = penshape::v1;
using namespace std::chrono_literals;

// A grouping session that counts the holds it recognizes (its clones count into the same).
class CountingSession final : public d::StrokeGroupSession {
 public:
  CountingSession(std::unique_ptr<d::StrokeGroupSession> inner,
                  std::shared_ptr<std::atomic<int>> holds)
      : inner_(std::move(inner)), holds_(std::move(holds)) {}
  using StrokeGroupSession::add;
  d::GroupedStrokeAnalysis add(const penshape::Stroke& stroke, bool with_ink,
                               const penshape::CancelHook& cancel,
                               const d::InkOffload& offload) override {
    return inner_->add(stroke, with_ink, cancel, offload);
  }
  d::GroupedStrokeAnalysis add_held(const penshape::Stroke& stroke,
                                    const penshape::CancelHook& cancel,
                                    const d::InkOffload& offload) override {
    ++*holds_;
    return inner_->add_held(stroke, cancel, offload);
  }
  [[nodiscard]] std::unique_ptr<d::StrokeGroupSession> clone() const override {
    return std::make_unique<CountingSession>(inner_->clone(), holds_);
  }
  [[nodiscard]] std::size_t stroke_count() const override { return inner_->stroke_count(); }

 private:
  std::unique_ptr<d::StrokeGroupSession> inner_;
  std::shared_ptr<std::atomic<int>> holds_;
};

class CountingAnalyzer final : public d::StrokeAnalyzer {
 public:
  d::StrokeAnalysis analyze(const penshape::Stroke& stroke, const d::PenSettings& settings,
                            const penshape::CancelHook& cancel) override {
    return inner_->analyze(stroke, settings, cancel);
  }
  std::unique_ptr<d::StrokeGroupSession> group_session(
      const d::PenSettings& settings, const penshape::GroupingConfig& grouping) override {
    return std::make_unique<CountingSession>(inner_->group_session(settings, grouping), holds);
  }
  std::shared_ptr<std::atomic<int>> holds = std::make_shared<std::atomic<int>>(0);

 private:
  std::shared_ptr<d::StrokeAnalyzer> inner_ = d::make_recognizing_analyzer();
};

// A circle of 15 mm radius drawn in 0.8 s at 1 kHz on a tablet of 100 units per mm, from time t0.
penshape::Stroke circle(std::uint64_t id, std::int64_t t0_us) {
  penshape::Stroke s;
  s.id = id;
  s.tablet.x_resolution = 100;
  s.tablet.y_resolution = 100;
  s.tablet.x_max = 100000;
  s.tablet.y_max = 100000;
  for (int i = 0; i <= 800; ++i) {
    const double a = 2 * std::numbers::pi * i / 800.0;
    penshape::PenSample p;
    p.x = static_cast<std::int32_t>(std::lround((50 + 15 * std::cos(a)) * 100));
    p.y = static_cast<std::int32_t>(std::lround((50 + 15 * std::sin(a)) * 100));
    p.time_us = t0_us + std::int64_t{i} * 1000;
    p.tip = true;
    p.in_range = true;
    s.samples.push_back(p);
  }
  return s;
}

struct Rig {
  std::shared_ptr<CountingAnalyzer> analyzer = std::make_shared<CountingAnalyzer>();
  d::DaemonState state{d::Limits{}, d::PenSettings{}, {}};
  std::atomic<int> running{0};
  d::LiveGrouping grouping{state, [this] { ++running; }, [this] { --running; }, nullptr};
  Rig() { state.analyzer = analyzer; }
  void wait_idle() {
    const auto until = std::chrono::steady_clock::now() + 60s;
    while (running.load() > 0 && std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(1ms);
    }
  }
  // Holds `partial`; returns its hold once the strand decided it.
  std::shared_ptr<d::HoldState> hold(const penshape::Stroke& partial) {
    auto held = std::make_shared<d::HoldState>();
    held->samples = partial.samples.size();
    held->time_us = partial.samples.back().time_us + 500000;
    grouping.hold("tablet", partial, held);
    wait_idle();
    return held;
  }
};

TEST(HoldPrepare, TheHoldOfTheRestPublishesTheAnswerRecognizedAhead) {
  Rig ahead;
  ahead.grouping.prepare_hold("tablet", circle(1, 0));
  ahead.wait_idle();
  EXPECT_EQ(ahead.analyzer->holds->load(), 1);
  const auto held = ahead.hold(circle(1, 0));
  EXPECT_EQ(ahead.analyzer->holds->load(), 1) << "the hold recognized the stroke again";
  ASSERT_EQ(held->phase, d::HoldState::Phase::kSnapped);

  Rig plain; // the same hold without the work ahead: the same answer
  const auto direct = plain.hold(circle(1, 0));
  ASSERT_EQ(direct->phase, d::HoldState::Phase::kSnapped);
  EXPECT_EQ(held->shape.SerializeAsString(), direct->shape.SerializeAsString());
  EXPECT_EQ(held->ink.SerializeAsString(), direct->ink.SerializeAsString());
  EXPECT_GT(held->ink.polygons_size(), 0) << "the ink the shape did not wait for is filled in";
}

TEST(HoldPrepare, WorkAheadIsNotUsedForAnotherRestOrAfterTheGroupingChanged) {
  Rig rig;
  rig.grouping.prepare_hold("tablet", circle(1, 0));
  rig.wait_idle();
  penshape::Stroke longer = circle(1, 0); // the pen moved on and rested again, later
  longer.samples.push_back(longer.samples.back());
  longer.samples.back().time_us += 1000;
  EXPECT_EQ(rig.hold(longer)->phase, d::HoldState::Phase::kSnapped);
  EXPECT_EQ(rig.analyzer->holds->load(), 2) << "another rest's stroke needs its own recognition";

  rig.grouping.prepare_hold("tablet", circle(2, 2'000'000));
  rig.wait_idle();
  rig.grouping.finish("tablet", circle(3, 1'000'000)); // another stroke joined the grouping
  rig.wait_idle();
  const int before = rig.analyzer->holds->load();
  EXPECT_EQ(rig.hold(circle(2, 2'000'000))->phase, d::HoldState::Phase::kSnapped);
  EXPECT_EQ(rig.analyzer->holds->load(), before + 1) << "work on a former grouping was used";

  rig.grouping.prepare_hold("tablet", circle(4, 3'000'000));
  rig.wait_idle();
  d::PenSettingsUpdate wider; // Config: the grouping starts afresh with the new pen
  wider.pen_radius_mm = 0.8;
  rig.state.settings.update("", wider, false);
  const int then = rig.analyzer->holds->load();
  EXPECT_EQ(rig.hold(circle(4, 3'000'000))->phase, d::HoldState::Phase::kSnapped);
  EXPECT_EQ(rig.analyzer->holds->load(), then + 1) << "work for the former settings was used";
}

} // namespace
