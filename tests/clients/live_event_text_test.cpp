// `penshape watch` prints what a grouped answer replaces: the strokes whose ink it replaces and
// the earlier shapes it supersedes, in its text line and its JSON object, and a preview's group;
// and a stroke's intent (writing is named, a shape without a decision says nothing).
#include "live_event_text.hpp"

#include <gtest/gtest.h>

namespace {

namespace v1 = penshape::v1;

v1::LiveEvent rectangle_upgrade() {
  v1::LiveEvent event;
  event.set_sequence(40);
  event.set_device_id("hidraw3");
  v1::ShapeRecognized* s = event.mutable_shape();
  s->set_stroke_id(4);
  s->mutable_shape()->set_kind(v1::SHAPE_KIND_RECTANGLE);
  s->set_shape_id(9);
  for (std::uint64_t id = 1; id <= 4; ++id) s->add_replaced_stroke_ids(id);
  s->add_supersedes_shape_ids(7);
  s->add_supersedes_sequences(31);
  s->add_tidy("axis");
  return event;
}

TEST(LiveEventText, ShapeLineNamesReplacedStrokesAndSupersededShapes) {
  const std::string line = penshape::cli::event_line(rectangle_upgrade());
  EXPECT_NE(line.find("[hidraw3] stroke 4 (shape 9) is a rectangle"), std::string::npos) << line;
  EXPECT_NE(line.find("; replaces strokes 1 2 3 4; supersedes shape 7; tidy axis"),
            std::string::npos)
      << line;
}

// The rectangle's upgrade event with its shape of `kind`: its line and kind name say `name`.
void expect_kind_named(v1::ShapeKind kind, const std::string& name) {
  v1::LiveEvent event = rectangle_upgrade();
  event.mutable_shape()->mutable_shape()->set_kind(kind);
  const std::string line = penshape::cli::event_line(event);
  EXPECT_NE(line.find("stroke 4 (shape 9) is a " + name), std::string::npos) << line;
  EXPECT_EQ(penshape::cli::shape_kind_name(kind), name);
}

TEST(LiveEventText, APolygonIsNamed) { expect_kind_named(v1::SHAPE_KIND_POLYGON, "polygon"); }

TEST(LiveEventText, ADiamondIsNamed) { expect_kind_named(v1::SHAPE_KIND_DIAMOND, "diamond"); }

TEST(LiveEventText, ShapeJsonNamesReplacedStrokesAndSupersededShapes) {
  const std::string json = penshape::cli::event_json(rectangle_upgrade());
  EXPECT_NE(json.find("\"shape_id\":9"), std::string::npos) << json;
  EXPECT_NE(json.find("\"replaced_stroke_ids\":[1,2,3,4]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"supersedes_shape_ids\":[7]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"supersedes_sequences\":[31]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"tidy\":[\"axis\"]"), std::string::npos) << json;
}

TEST(LiveEventText, LoneShapeLineIsUnchangedButForItsId) {
  v1::LiveEvent event;
  event.set_device_id("hidraw3");
  event.mutable_shape()->set_stroke_id(5);
  event.mutable_shape()->mutable_shape()->set_kind(v1::SHAPE_KIND_NONE);
  EXPECT_EQ(penshape::cli::event_line(event).find("replaces"), std::string::npos);
  EXPECT_EQ(penshape::cli::event_line(event).find("(shape"), std::string::npos);
}

TEST(LiveEventText, PreviewOfAGroupNamesItsStrokes) {
  v1::LiveEvent event;
  event.set_device_id("hidraw3");
  v1::PreviewCandidates* p = event.mutable_preview();
  p->set_stroke_id(4);
  p->mutable_group()->mutable_shape()->set_kind(v1::SHAPE_KIND_RECTANGLE);
  for (std::uint64_t id = 1; id <= 4; ++id) p->mutable_group()->add_replaced_stroke_ids(id);
  p->mutable_group()->add_supersedes_shape_ids(7);
  const std::string line = penshape::cli::event_line(event);
  EXPECT_NE(line.find("with earlier strokes: rectangle"), std::string::npos) << line;
  EXPECT_NE(line.find("replaces strokes 1 2 3 4; supersedes shape 7"), std::string::npos) << line;
  EXPECT_NE(penshape::cli::event_json(event).find("\"group\":{"), std::string::npos);
}

// An arrow's parameters in the shape's JSON object, a bent shaft's bends included (tail to tip).
TEST(LiveEventText, ArrowJsonHasItsShaftBends) {
  v1::LiveEvent event;
  event.set_device_id("hidraw3");
  v1::Shape* shape = event.mutable_shape()->mutable_shape();
  shape->set_kind(v1::SHAPE_KIND_ARROW);
  v1::ArrowParams* a = shape->mutable_arrow();
  auto set = [](v1::Point* p, double x, double y) {
    p->set_x(x);
    p->set_y(y);
  };
  set(a->mutable_tail(), 0, 0);
  set(a->mutable_tip(), 100, -30);
  set(a->add_barbs(), 90, -16);
  set(a->add_barbs(), 84, -24);
  set(a->add_shaft_bends(), 40, 2);
  set(a->add_shaft_bends(), 60, 0);
  a->set_head_angle_rad(0.5);
  const std::string json = penshape::cli::event_json(event);
  EXPECT_NE(json.find("\"arrow\":{\"tail\":[0,0],\"tip\":[100,-30],"
                      "\"barbs\":[[90,-16],[84,-24]],\"tail_barbs\":[],"
                      "\"head_angle_rad\":0.5,\"shaft_bulge\":0,"
                      "\"shaft_bends\":[[40,2],[60,0]]}"),
            std::string::npos)
      << json;
}

} // namespace

namespace {

// Hold to snap: a HOLD, FOLLOW or RELEASE shape names its trigger and hold in JSON and text.
TEST(LiveEventText, HoldSnapsNameTheirTriggerAndHold) {
  v1::LiveEvent event = rectangle_upgrade();
  v1::ShapeRecognized* s = event.mutable_shape();
  s->set_trigger(v1::SHAPE_TRIGGER_HOLD);
  s->mutable_shape()->mutable_certificate()->set_scope("drawn_part");
  s->mutable_hold()->set_certified_samples(120);
  s->mutable_hold()->mutable_hold_point()->set_x(10);
  s->mutable_hold()->set_held_shape_id(9);
  std::string json = penshape::cli::event_json(event);
  EXPECT_NE(json.find("\"type\":\"shape\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"trigger\":\"hold\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"hold\":{\"certified_samples\":120,\"hold_point\":[10,0]"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"scope\":\"drawn_part\""), std::string::npos) << json;
  EXPECT_NE(penshape::cli::event_line(event).find("(held, pen down) is a rectangle"),
            std::string::npos)
      << penshape::cli::event_line(event);
  s->set_trigger(v1::SHAPE_TRIGGER_RELEASE);
  s->mutable_hold()->set_adjusted(true);
  EXPECT_NE(penshape::cli::event_json(event).find("\"trigger\":\"release\""), std::string::npos);
  EXPECT_NE(penshape::cli::event_line(event).find("(released, adjusted by the drag)"),
            std::string::npos);
  s->clear_hold();
  s->set_trigger(v1::SHAPE_TRIGGER_UNSPECIFIED); // an older daemon: pen-up
  json = penshape::cli::event_json(event);
  EXPECT_NE(json.find("\"trigger\":\"pen_up\""), std::string::npos) << json;
  EXPECT_EQ(json.find("\"hold\""), std::string::npos) << json;
}

} // namespace

namespace {

v1::LiveEvent writing_stroke() {
  v1::LiveEvent event;
  event.set_device_id("hidraw3");
  v1::Shape* shape = event.mutable_shape()->mutable_shape();
  event.mutable_shape()->set_stroke_id(6);
  shape->set_kind(v1::SHAPE_KIND_NONE);
  shape->set_intent(v1::INTENT_WRITING);
  shape->set_writing_score(0.875);
  return event;
}

TEST(LiveEventText, WritingIsNamedInTextAndJson) {
  const std::string line = penshape::cli::event_line(writing_stroke());
  EXPECT_NE(line.find("stroke 6 is freeform (writing, P 0.88)"), std::string::npos) << line;
  const std::string json = penshape::cli::event_json(writing_stroke());
  EXPECT_NE(json.find("\"intent\":\"writing\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"writing_score\":0.875"), std::string::npos) << json;
  v1::LiveEvent drawing = rectangle_upgrade();
  drawing.mutable_shape()->mutable_shape()->set_intent(v1::INTENT_DRAWING);
  EXPECT_NE(penshape::cli::event_json(drawing).find("\"intent\":\"drawing\""), std::string::npos);
  EXPECT_EQ(penshape::cli::event_json(rectangle_upgrade()).find("\"intent\""), std::string::npos)
      << "no decision made: no intent";
}

} // namespace
