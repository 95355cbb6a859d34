// The writing/drawing decision (core intent.hpp): generated writing and shapes (a bare clone),
// live use one stroke at a time, dots, untimed strokes, bad input, units, the grouper that leaves
// writing alone; real UNIPEN handwriting and $1 shapes (alone, untimed) under the shared-data skip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "generated_ink.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/core/intent.hpp"
#include "penshape/core/intent_grouper.hpp"
#include "support/dollar1.hpp"
#include "test_data.hpp"

namespace {

using penshape::Intent;
using penshape::StrokePoint;
using penshape::test::ink::PageStroke;
using penshape::test::ink::Points;

std::vector<Points> points_of(const std::vector<PageStroke>& page) {
  std::vector<Points> out;
  out.reserve(page.size());
  for (const PageStroke& s : page) out.push_back(s.points);
  return out;
}

// Strokes decided against their truth, writing and drawing apart.
struct Errors {
  int writing_as_drawing = 0, writing = 0, drawing_as_writing = 0, drawing = 0;
};

Errors errors_on(const std::vector<PageStroke>& page, const penshape::IntentConfig& config = {}) {
  const auto d = penshape::decide_intent(points_of(page), config);
  Errors e;
  for (std::size_t i = 0; i < page.size(); ++i) {
    if (page[i].writing) {
      ++e.writing;
      e.writing_as_drawing += d[i].intent == Intent::kDrawing ? 1 : 0;
    } else {
      ++e.drawing;
      e.drawing_as_writing += d[i].intent == Intent::kWriting ? 1 : 0;
    }
  }
  return e;
}

TEST(Intent, GeneratedWritingIsWriting) {
  const auto page = penshape::test::ink::note_page(6, false);
  const Errors e = errors_on(page);
  ASSERT_GT(e.writing, 60);
  EXPECT_EQ(e.writing_as_drawing, 0) << "of " << e.writing;
}

TEST(Intent, GeneratedShapesBetweenLinesAreDrawing) {
  const auto page = penshape::test::ink::note_page(6, true);
  const Errors e = errors_on(page);
  ASSERT_EQ(e.drawing, 15);
  EXPECT_EQ(e.drawing_as_writing, 0);
  EXPECT_EQ(e.writing_as_drawing, 0) << "of " << e.writing;
}

// Live use: LiveIntent's decision of each stroke is decide_intent's on the last 24 strokes and it
// (bit for bit), with a stroke remembered without a decision (a held one) in the context too.
TEST(Intent, LiveIntentDecidesAsThePageOfRecentStrokes) {
  const std::vector<Points> strokes = points_of(penshape::test::ink::note_page(6, true));
  ASSERT_GT(strokes.size(), 40U);
  penshape::LiveIntent live;
  std::vector<Points> recent;
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    if (i % 7 == 3) {
      live.remember(strokes[i]);
    } else {
      std::vector<Points> page = recent;
      page.push_back(strokes[i]);
      const penshape::IntentDecision want = penshape::decide_intent(page).back();
      const penshape::IntentDecision got = live.add(strokes[i]);
      EXPECT_EQ(got.intent, want.intent) << "stroke " << i;
      EXPECT_EQ(got.writing_score, want.writing_score) << "stroke " << i;
    }
    recent.push_back(strokes[i]);
    if (recent.size() > 24) recent.erase(recent.begin());
  }
  EXPECT_THROW(penshape::LiveIntent({.writing_threshold = 2.0}), penshape::InvalidInput);
}

TEST(Intent, ShapesAloneAreDrawing) {
  double t = 0;
  for (const Points& shape : penshape::test::ink::shapes_at(20, 20, t)) {
    const auto d = penshape::decide_intent(std::vector<Points>{shape});
    EXPECT_EQ(d.front().intent, Intent::kDrawing) << "P(writing) " << d.front().writing_score;
  }
}

// Without times (t all 0) the decision rests on the geometry and the page alone.
TEST(Intent, UntimedStrokesAreDecidedToo) {
  auto page = penshape::test::ink::note_page(6, true);
  for (PageStroke& s : page) {
    for (StrokePoint& p : s.points) p.t = 0;
  }
  const Errors e = errors_on(page);
  EXPECT_EQ(e.drawing_as_writing, 0);
  EXPECT_EQ(e.writing_as_drawing, 0) << "of " << e.writing;
}

TEST(Intent, UnitsFollowMmPerUnit) {
  auto page = penshape::test::ink::note_page(4, true);
  const auto in_mm = penshape::decide_intent(points_of(page));
  for (PageStroke& s : page) {
    for (StrokePoint& p : s.points) p.x *= 10, p.y *= 10; // tenths of a millimetre
  }
  const auto in_tenths = penshape::decide_intent(points_of(page), {.mm_per_unit = 0.1});
  ASSERT_EQ(in_mm.size(), in_tenths.size());
  for (std::size_t i = 0; i < in_mm.size(); ++i) {
    EXPECT_NEAR(in_mm[i].writing_score, in_tenths[i].writing_score, 1e-9) << i;
  }
}

TEST(Intent, DotsAreWritingNeverErrors) {
  const Points dot{{10, 10, 0}};
  const Points still{{10, 10, 0}, {10, 10, 0.01}, {10, 10, 0.02}};
  const Points empty;
  const auto d = penshape::decide_intent(std::vector<Points>{dot, still, empty});
  ASSERT_EQ(d.size(), 3U);
  for (const auto& x : d) {
    EXPECT_EQ(x.intent, Intent::kWriting);
    EXPECT_EQ(x.writing_score, 1.0);
  }
  EXPECT_TRUE(penshape::decide_intent(std::vector<Points>{}).empty());
}

TEST(Intent, BadInputIsAClearError) {
  const Points nan{{0, 0, 0}, {std::numeric_limits<double>::quiet_NaN(), 1, 0.01}};
  EXPECT_THROW(penshape::decide_intent(std::vector<Points>{nan}), penshape::InvalidInput);
  const Points ok{{0, 0, 0}, {1, 1, 0.01}};
  EXPECT_THROW(penshape::decide_intent(std::vector<Points>{ok}, {.mm_per_unit = 0}),
               penshape::InvalidInput);
  EXPECT_THROW(penshape::decide_intent(std::vector<Points>{ok}, {.writing_threshold = 2}),
               penshape::InvalidInput);
}

TEST(Intent, FeaturesAreFiniteAndNamed) {
  const auto page = points_of(penshape::test::ink::note_page(3, true));
  const std::vector<penshape::IntentStroke> spans(page.begin(), page.end());
  for (const auto& f : penshape::intent_features(spans)) {
    for (const double v : f) EXPECT_TRUE(std::isfinite(v));
  }
  EXPECT_EQ(penshape::intent_feature_names().back(), "writing_height");
}

// A t-bar is a clean segment: snapped with the filter off, left alone with it on.
TEST(IntentGrouper, WritingStaysFreeformAndApart) {
  double t = 0;
  const Points bar = penshape::test::ink::traced({{0, 0}, {3, 0.1}}, t);
  const Points dot{{1, -3, t + 0.1}};
  penshape::RecognizerConfig config;
  config.pen_radius = 0.35;
  for (const bool snap_writing : {false, true}) {
    penshape::IntentGrouper grouper({}, config, snap_writing);
    penshape::StrokeInput input;
    input.samples = bar;
    const auto update = grouper.add(input, Intent::kWriting);
    EXPECT_EQ(update.shape.strokes, std::vector<std::size_t>{0});
    EXPECT_EQ(update.shape.recognition.shape == penshape::ShapeClass::kFreeform, !snap_writing);
    if (snap_writing) continue;
    input.samples = dot; // never reaches the recognizer
    EXPECT_NO_THROW(grouper.add(input, Intent::kWriting));
    const auto shapes = grouper.shapes();
    ASSERT_EQ(shapes.size(), 2U);
    EXPECT_NE(shapes[0].id, shapes[1].id);
    // A writing dot is writing like any other stroke: freeform, no error.
    EXPECT_EQ(shapes[1].recognition.shape, penshape::ShapeClass::kFreeform);
  }
}

TEST(IntentGrouper, AStrokeWithoutSamplesIsRefused) {
  penshape::IntentGrouper grouper;
  EXPECT_THROW(grouper.add({}, Intent::kWriting), penshape::InvalidInput);
  EXPECT_TRUE(grouper.shapes().empty());
}

// A short stroke (a t-bar) from time t on.
penshape::StrokeInput bar(double& t) {
  penshape::StrokeInput input;
  input.samples = penshape::test::ink::traced({{0, 0}, {2, 0}}, t);
  return input;
}

TEST(IntentGrouper, DrawingStrokesKeepTheirPageIndices) {
  double t = 0;
  penshape::IntentGrouper grouper;
  penshape::StrokeInput input = bar(t);
  grouper.add(input, Intent::kWriting);
  input.samples = penshape::test::ink::circle(40, 40, 15, t);
  const auto update = grouper.add(input, Intent::kDrawing);
  EXPECT_EQ(update.shape.strokes, std::vector<std::size_t>{1});
  EXPECT_EQ(update.shape.recognition.shape, penshape::ShapeClass::kCircle);
  const auto shapes = grouper.shapes();
  ASSERT_EQ(shapes.size(), 2U);
  EXPECT_EQ(shapes[1].strokes, std::vector<std::size_t>{1});
}

TEST(IntentGrouper, ForgetsWritingAnswersAndKeepsCounting) {
  double t = 0;
  penshape::IntentGrouper grouper;
  const penshape::StrokeInput input = bar(t);
  grouper.add(input, Intent::kWriting);
  grouper.forget_unreachable();
  EXPECT_TRUE(grouper.shapes().empty());
  const auto update = grouper.add(input, Intent::kWriting);
  EXPECT_EQ(update.shape.strokes, std::vector<std::size_t>{1});
  EXPECT_EQ(grouper.shapes().size(), 1U);
}

std::vector<Points> read_jsonl(const std::filesystem::path& file) {
  std::vector<Points> strokes;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    Points s;
    // Named: a range-for over a temporary's member would read freed memory.
    const auto item = nlohmann::json::parse(line);
    for (const auto& p : item.at("points")) {
      s.push_back({p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>()});
    }
    strokes.push_back(std::move(s));
  }
  return strokes;
}

// Real handwriting (UNIPEN, every item as a page): nearly all of it writing. The rate is the
// committed weights on data they learned from; the held-out figures are intent_bench's.
TEST(IntentRealData, UnipenHandwritingIsWriting) {
  PENSHAPE_SHARED_OR_SKIP(dir, "strokes/handwriting-unipen/pages");
  int strokes = 0, drawing = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    for (const auto& d : penshape::decide_intent(read_jsonl(e.path()))) {
      ++strokes;
      drawing += d.intent == Intent::kDrawing ? 1 : 0;
    }
  }
  EXPECT_GT(strokes, 3000);
  EXPECT_LT(drawing, strokes / 50) << drawing << " of " << strokes << " decided drawing";
}

// Real shapes ($1 logs: triangles, circles, rectangles, arrows of subjects s02-s11, untimed
// here), each alone on its page at 20-60 mm: drawing.
TEST(IntentRealData, DollarShapesAloneAreDrawing) {
  PENSHAPE_SHARED_OR_SKIP(dir, "strokes/dollar1");
  int shapes = 0, writing = 0;
  for (const char* name : {"triangle", "circle", "rectangle", "arrow"}) {
    for (int subject = 2; subject <= 11; ++subject) {
      for (int k = 1; k <= 10; ++k) {
        char file[64];
        std::snprintf(file, sizeof file, "s%02d/medium/%s%02d.xml", subject, name, k);
        if (!std::filesystem::exists(dir / file)) continue;
        const auto pts = penshape::test::read_dollar1((dir / file).string());
        double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
        for (const auto& p : pts) {
          x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y),
          y1 = std::max(y1, p.y);
        }
        const double scale = (20.0 + 4.0 * (k - 1)) / std::max(x1 - x0, y1 - y0);
        Points stroke;
        for (const auto& p : pts) stroke.push_back({p.x * scale, p.y * scale, 0.0});
        ++shapes;
        const auto d = penshape::decide_intent(std::vector<Points>{stroke});
        writing += d.front().intent == Intent::kWriting ? 1 : 0;
      }
    }
  }
  EXPECT_GT(shapes, 150);
  EXPECT_LT(writing, shapes / 50) << writing << " of " << shapes << " decided writing";
  std::printf("%d of %d lone untimed $1 shapes decided writing\n", writing, shapes);
}

} // namespace
