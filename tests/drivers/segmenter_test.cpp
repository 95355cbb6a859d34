// Stroke segmentation and the junk accounting of the pipeline.
#include "penshape/drivers/stroke_segmenter.hpp"

#include <gtest/gtest.h>

#include "penshape/drivers/pen_pipeline.hpp"

namespace penshape::drivers {
namespace {

PenSample at(std::int64_t t, bool tip, bool in_range = true, int x = 0) {
  PenSample s;
  s.time_us = t;
  s.tip = tip;
  s.in_range = in_range;
  s.x = x;
  s.pressure = tip ? 100U : 0U;
  return s;
}

std::vector<Stroke> run(StrokeSegmenter& seg, const std::vector<PenSample>& samples) {
  std::vector<Stroke> out;
  for (const auto& s : samples) {
    if (auto st = seg.feed(s)) out.push_back(std::move(*st));
  }
  if (auto st = seg.finish()) out.push_back(std::move(*st));
  return out;
}

TEST(StrokeSegmenter, TipDownToTipUp) {
  StrokeSegmenter seg({}, {.tip_up_debounce_us = 0, .silence_timeout_us = 0});
  const auto strokes =
      run(seg, {at(0, false), at(10, true, true, 1), at(20, true, true, 2), at(30, false, true, 3),
                at(40, false), at(50, true, true, 5), at(60, false, true, 6)});
  ASSERT_EQ(strokes.size(), 2U);
  EXPECT_EQ(strokes[0].samples.size(), 3U);
  EXPECT_EQ(strokes[0].samples.back().x, 3);
  EXPECT_FALSE(strokes[0].samples.back().tip);
  EXPECT_EQ(strokes[1].samples.size(), 2U);
  EXPECT_EQ(strokes[0].id + 1, strokes[1].id);
}

TEST(StrokeSegmenter, ShortTipUpIsABounce) {
  StrokeSegmenter seg({}, {.tip_up_debounce_us = 12000, .silence_timeout_us = 0});
  // Up for 4 ms then down again: one stroke, the hover sample dropped.
  const auto strokes = run(seg, {at(0, true), at(4000, true), at(8000, false), at(12000, true),
                                 at(16000, true), at(20000, false), at(40000, false)});
  ASSERT_EQ(strokes.size(), 1U);
  EXPECT_EQ(strokes[0].samples.size(), 5U);
  EXPECT_EQ(strokes[0].samples.back().time_us, 20000);
}

TEST(StrokeSegmenter, LongTipUpEndsTheStrokeAtTheFirstUpSample) {
  StrokeSegmenter seg({}, {.tip_up_debounce_us = 12000, .silence_timeout_us = 0});
  const auto strokes = run(seg, {at(0, true), at(4000, false), at(20000, true), at(24000, false)});
  ASSERT_EQ(strokes.size(), 2U);
  EXPECT_EQ(strokes[0].samples.back().time_us, 4000);
  EXPECT_EQ(strokes[1].samples.front().time_us, 20000);
}

TEST(StrokeSegmenter, LeavingProximityEndsTheStroke) {
  StrokeSegmenter seg({}, {.tip_up_debounce_us = 12000, .silence_timeout_us = 0});
  std::vector<Stroke> out;
  EXPECT_FALSE(seg.feed(at(0, true, true, 7)));
  auto st = seg.feed(at(1000, false, false, 8));
  ASSERT_TRUE(st);
  EXPECT_EQ(st->samples.size(), 2U);
  EXPECT_FALSE(st->samples.back().in_range);
  EXPECT_FALSE(seg.in_stroke());
}

TEST(StrokeSegmenter, IdleExpiresDebounceAndSilence) {
  StrokeSegmenter seg({}, {.tip_up_debounce_us = 12000, .silence_timeout_us = 250000});
  EXPECT_FALSE(seg.feed(at(0, true)));
  EXPECT_FALSE(seg.feed(at(4000, false)));
  EXPECT_FALSE(seg.idle(10000));
  ASSERT_TRUE(seg.idle(16000));
  EXPECT_FALSE(seg.feed(at(20000, true)));
  EXPECT_FALSE(seg.idle(200000));
  auto st = seg.idle(270000); // the tablet went silent with the tip down
  ASSERT_TRUE(st);
  EXPECT_FALSE(st->samples.back().tip);
}

TEST(StrokeSegmenter, FinishWithoutStrokeIsNothing) {
  StrokeSegmenter seg({});
  EXPECT_FALSE(seg.finish());
  EXPECT_FALSE(seg.feed(at(0, false)));
  EXPECT_FALSE(seg.finish());
}

TEST(PenPipeline, JunkIsDroppedAndCounted) {
  // A generic pen: report ID 2, tip bit, in-range bit, X and Y 16 bits (max 1000), pressure 8.
  const std::vector<std::uint8_t> desc = {
      0x05, 0x0D, 0x09, 0x02, 0xA1, 0x01, 0x85, 0x02, 0x09, 0x42, 0x09, 0x32, 0x15, 0x00,
      0x25, 0x01, 0x75, 0x01, 0x95, 0x02, 0x81, 0x02, 0x95, 0x06, 0x81, 0x03, 0x05, 0x01,
      0x09, 0x30, 0x09, 0x31, 0x26, 0xE8, 0x03, 0x75, 0x10, 0x95, 0x02, 0x81, 0x02, 0x05,
      0x0D, 0x09, 0x30, 0x26, 0xFF, 0x00, 0x75, 0x08, 0x95, 0x01, 0x81, 0x02, 0xC0};
  const DeviceProfile profile = build_profile({Bus::kUsb, 0x1111, 0x2222, "pen"}, desc);
  ASSERT_TRUE(profile.has_pen());
  EXPECT_EQ(profile.info.x_max, 1000);
  std::vector<Stroke> strokes;
  PenPipeline p(profile, {.tip_up_debounce_us = 0, .silence_timeout_us = 0},
                {.on_sample = {}, .on_stroke = [&](Stroke&& s) { strokes.push_back(s); }});
  using B = std::vector<std::uint8_t>;
  p.on_report(B{0x02, 0x03, 0x10, 0x00, 0x20, 0x00, 0x40}, 0); // tip down
  p.on_report(B{0x02, 0x03, 0x10}, 1);                         // short: junk
  p.on_report(B{0x05, 0x03, 0x10, 0x00, 0x20, 0x00, 0x40}, 2); // unknown ID: junk
  p.on_report(B{}, 3);                                         // empty: junk
  p.on_report(B{0x02, 0x03, 0xFF, 0xFF, 0x20, 0x00, 0x40}, 4); // x 65535 > 1000: dropped
  p.on_report(B{0x02, 0x03, 0x11, 0x00, 0x20, 0x00, 0x40}, 5);
  p.on_report(B{0x02, 0x02, 0x12, 0x00, 0x20, 0x00, 0x00}, 6); // tip up
  EXPECT_EQ(p.counters().reports, 7U);
  EXPECT_EQ(p.counters().junk_reports, 3U);
  EXPECT_EQ(p.counters().out_of_range, 1U);
  EXPECT_EQ(p.counters().pen_samples, 3U);
  ASSERT_EQ(strokes.size(), 1U);
  EXPECT_EQ(strokes[0].samples.size(), 3U);
  EXPECT_EQ(strokes[0].samples[0].pressure, 0x40U);
  EXPECT_EQ(strokes[0].samples[1].x, 0x11);
}

} // namespace
} // namespace penshape::drivers
