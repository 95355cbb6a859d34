#include "live_event_text.hpp"

#include <cstdio>
#include <initializer_list>
#include <string_view>

#include "penshape/types/lookup_table.hpp"

namespace penshape::cli {
namespace {

template <typename... T>
std::string format(const char* fmt, T... values) {
  char buf[128];
  std::snprintf(buf, sizeof buf, fmt, values...);
  return buf;
}

std::string hex4(std::uint32_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%04x", v & 0xffffU);
  return buf;
}

void write_point(JsonWriter& json, const v1::Point& p) {
  json.begin_array().number(p.x()).number(p.y()).end_array();
}

void write_tablet_fields(JsonWriter& json, const v1::TabletInfo& t) {
  json.key("name").string(t.name());
  json.key("vendor_id").integer(t.vendor_id());
  json.key("product_id").integer(t.product_id());
  json.key("bus").integer(static_cast<int>(t.bus()));
  json.key("x_max").integer(t.x_max());
  json.key("y_max").integer(t.y_max());
  json.key("pressure_max").integer(t.pressure_max());
  json.key("x_resolution").number(t.x_resolution());
  json.key("y_resolution").number(t.y_resolution());
  json.key("has_tilt").boolean(t.has_tilt());
  json.key("width_mm").number(t.x_resolution() > 0 ? t.x_max() / t.x_resolution() : 0.0);
  json.key("height_mm").number(t.y_resolution() > 0 ? t.y_max() / t.y_resolution() : 0.0);
}

void write_sample_json(JsonWriter& json, const v1::PenSample& s) {
  json.begin_object();
  json.key("time_us").integer(s.time_us());
  json.key("x").integer(s.x());
  json.key("y").integer(s.y());
  json.key("pressure").integer(s.pressure());
  json.key("tilt_x").integer(s.tilt_x());
  json.key("tilt_y").integer(s.tilt_y());
  json.key("buttons").integer(s.buttons());
  json.key("in_range").boolean(s.in_range());
  json.key("tip").boolean(s.tip());
  json.end_object();
}

void write_ids(JsonWriter& json, const char* key,
               const google::protobuf::RepeatedField<std::uint64_t>& ids) {
  json.key(key).begin_array();
  for (const std::uint64_t id : ids) json.integer(static_cast<std::int64_t>(id));
  json.end_array();
}

void write_tidy(JsonWriter& json, const google::protobuf::RepeatedPtrField<std::string>& tidy) {
  json.key("tidy").begin_array();
  for (const std::string& t : tidy) json.string(t);
  json.end_array();
}

// " 1 2 3" for a list of ids.
std::string id_list(const google::protobuf::RepeatedField<std::uint64_t>& ids) {
  std::string out;
  for (const std::uint64_t id : ids) {
    out += ' ';
    out += std::to_string(id);
  }
  return out;
}

// What a grouped answer replaces: "; replaces strokes 1 2 3 4; supersedes shape 7; tidy axis".
std::string grouping_text(const google::protobuf::RepeatedField<std::uint64_t>& strokes,
                          const google::protobuf::RepeatedField<std::uint64_t>& shapes,
                          const google::protobuf::RepeatedPtrField<std::string>& tidy) {
  std::string out;
  if (strokes.size() > 1) out += "; replaces strokes" + id_list(strokes);
  if (!shapes.empty())
    out += std::string("; supersedes shape") + (shapes.size() > 1 ? "s" : "") + id_list(shapes);
  if (!tidy.empty()) {
    out += "; tidy";
    for (const std::string& t : tidy) {
      out += ' ';
      out += t;
    }
  }
  return out;
}

} // namespace

std::string shape_kind_name(v1::ShapeKind kind) {
  switch (kind) {
    case v1::SHAPE_KIND_NONE:
      return "freeform"; // nothing certified: the recognizer's name for it
    case v1::SHAPE_KIND_SEGMENT:
      return "segment";
    case v1::SHAPE_KIND_POLYLINE:
      return "polyline";
    case v1::SHAPE_KIND_TRIANGLE:
      return "triangle";
    case v1::SHAPE_KIND_QUADRILATERAL:
      return "quadrilateral";
    case v1::SHAPE_KIND_RECTANGLE:
      return "rectangle";
    case v1::SHAPE_KIND_SQUARE:
      return "square";
    case v1::SHAPE_KIND_DIAMOND:
      return "diamond";
    case v1::SHAPE_KIND_REGULAR_POLYGON:
      return "regular_polygon";
    case v1::SHAPE_KIND_CIRCLE:
      return "circle";
    case v1::SHAPE_KIND_ELLIPSE:
      return "ellipse";
    case v1::SHAPE_KIND_ARC:
      return "arc";
    case v1::SHAPE_KIND_ARROW:
      return "arrow";
    case v1::SHAPE_KIND_DOUBLE_ARROW:
      return "double_arrow";
    case v1::SHAPE_KIND_DOT:
      return "dot";
    case v1::SHAPE_KIND_POLYGON:
      return "polygon";
    default:
      return "unspecified";
  }
}

std::string shape_summary(const v1::Shape& shape) {
  std::string out = shape_kind_name(shape.kind());
  if (shape.intent() == v1::INTENT_WRITING) { // left as drawn (unless snap_writing)
    out += format(" (writing, P %.2f)", shape.writing_score());
  }
  if (shape.kind() == v1::SHAPE_KIND_NONE || shape.kind() == v1::SHAPE_KIND_UNSPECIFIED) {
    return out;
  }
  switch (shape.params_case()) {
    case v1::Shape::kVertices:
      out += " with " + std::to_string(shape.vertices().vertices_size()) + " vertices";
      break;
    case v1::Shape::kCircle:
      out += format(" r=%.2f mm at (%.2f, %.2f)", shape.circle().radius(),
                    shape.circle().center().x(), shape.circle().center().y());
      break;
    default:
      break;
  }
  out += format(" confidence %.2f, H <= %.3g mm", shape.confidence(),
                shape.certificate().hausdorff_bound().approx());
  return out;
}

void write_device_json(JsonWriter& json, const v1::DeviceInfo& device) {
  json.begin_object();
  json.key("id").string(device.id());
  json.key("settings_key").string(device.settings_key());
  write_tablet_fields(json, device.tablet());
  json.key("source").string(device.source());
  json.key("replay").boolean(device.replay());
  json.end_object();
}

std::string device_line(const v1::DeviceInfo& device) {
  const v1::TabletInfo& t = device.tablet();
  std::string area = "size unknown";
  if (t.x_resolution() > 0 && t.y_resolution() > 0) {
    area = format("%.1f x %.1f mm", t.x_max() / t.x_resolution(), t.y_max() / t.y_resolution());
  }
  return device.id() + "  " + hex4(t.vendor_id()) + ":" + hex4(t.product_id()) + "  " +
         (t.name().empty() ? "(unnamed)" : t.name()) + "  " + area + "  " + device.source() +
         (device.replay() ? "  (replay)" : "");
}

namespace {

// ArrowParams as "arrow" {tail, tip, barbs, tail_barbs, head_angle_rad, shaft_bulge,
// shaft_bends, shaft_end (only when the shaft stops short of the tip)}.
void write_arrow_json(JsonWriter& json, const v1::ArrowParams& a) {
  auto points = [&](const char* key, const auto& list) {
    json.key(key).begin_array();
    for (const auto& p : list) write_point(json, p);
    json.end_array();
  };
  json.key("arrow").begin_object();
  json.key("tail");
  write_point(json, a.tail());
  json.key("tip");
  write_point(json, a.tip());
  points("barbs", a.barbs());
  points("tail_barbs", a.tail_barbs());
  json.key("head_angle_rad").number(a.head_angle_rad());
  json.key("shaft_bulge").number(a.shaft_bulge());
  points("shaft_bends", a.shaft_bends());
  if (a.has_shaft_end()) {
    json.key("shaft_end");
    write_point(json, a.shaft_end());
  }
  json.end_object();
}

// A round shape's parameters: "name": {"center": [x, y], then the numbers in order}.
void write_round_json(JsonWriter& json, const char* name, const v1::Point& center,
                      std::initializer_list<std::pair<const char*, double>> numbers) {
  json.key(name).begin_object();
  json.key("center");
  write_point(json, center);
  for (const auto& [key, value] : numbers) json.key(key).number(value);
  json.end_object();
}

} // namespace

void write_shape_json(JsonWriter& json, const v1::Shape& shape) {
  json.begin_object();
  json.key("kind").string(shape_kind_name(shape.kind()));
  json.key("confidence").number(shape.confidence());
  if (shape.intent() != v1::INTENT_UNSPECIFIED) { // absent when the daemon made no decision
    json.key("intent").string(shape.intent() == v1::INTENT_WRITING ? "writing" : "drawing");
    json.key("writing_score").number(shape.writing_score());
  }
  switch (shape.params_case()) {
    case v1::Shape::kVertices:
      json.key("vertices").begin_array();
      for (const auto& p : shape.vertices().vertices()) write_point(json, p);
      json.end_array();
      break;
    case v1::Shape::kCircle:
      write_round_json(json, "circle", shape.circle().center(),
                       {{"radius", shape.circle().radius()}});
      break;
    case v1::Shape::kEllipse: {
      const v1::EllipseParams& e = shape.ellipse();
      write_round_json(json, "ellipse", e.center(),
                       {{"semi_major", e.semi_major()},
                        {"semi_minor", e.semi_minor()},
                        {"rotation_rad", e.rotation_rad()}});
      break;
    }
    case v1::Shape::kArc: {
      const v1::ArcParams& a = shape.arc();
      write_round_json(
          json, "arc", a.center(),
          {{"radius", a.radius()}, {"start_rad", a.start_rad()}, {"sweep_rad", a.sweep_rad()}});
      break;
    }
    case v1::Shape::kArrow:
      write_arrow_json(json, shape.arrow());
      break;
    default:
      break;
  }
  if (shape.has_certificate()) {
    json.key("hausdorff_bound").string(shape.certificate().hausdorff_bound().rational());
    json.key("tolerance").string(shape.certificate().tolerance().rational());
    json.key("pen_radius").string(shape.certificate().pen_radius().rational());
    json.key("method").string(shape.certificate().method());
    if (!shape.certificate().scope().empty()) {
      json.key("scope").string(shape.certificate().scope());
    }
  }
  json.end_object();
}

std::string answer_word(v1::Answer a) {
  static constexpr LookupTable<v1::Answer, const char*, 3> kWords{
      {{v1::ANSWER_YES, "YES"}, {v1::ANSWER_NO, "NO"}, {v1::ANSWER_UNDECIDED, "UNDECIDED"}}};
  return lookup_or(kWords, a, "unknown");
}

std::string millimetres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g mm", v);
  return buf;
}

namespace {

// The trigger of a ShapeRecognized as a word ("pen_up" for daemons older than hold to snap).
std::string trigger_name(v1::ShapeTrigger trigger) {
  static constexpr LookupTable<v1::ShapeTrigger, const char*, 3> kNames{
      {{v1::SHAPE_TRIGGER_HOLD, "hold"},
       {v1::SHAPE_TRIGGER_FOLLOW, "follow"},
       {v1::SHAPE_TRIGGER_RELEASE, "release"}}};
  return lookup_or(kNames, trigger, "pen_up");
}

// "hold":{"certified_samples","hold_point":[x,y],"pen_point":[x,y],"adjusted","held_shape_id"}
void write_hold_json(JsonWriter& json, const v1::HoldSnap& h) {
  json.key("hold").begin_object();
  json.key("certified_samples").integer(h.certified_samples());
  json.key("hold_point");
  write_point(json, h.hold_point());
  json.key("pen_point");
  write_point(json, h.pen_point());
  json.key("adjusted").boolean(h.adjusted());
  json.key("held_shape_id").integer(static_cast<std::int64_t>(h.held_shape_id()));
  json.end_object();
}

// " (hold)", " (follows the pen)", " (released, adjusted)": "" for a pen-up snap.
std::string hold_text(const v1::ShapeRecognized& r) {
  switch (r.trigger()) {
    case v1::SHAPE_TRIGGER_HOLD:
      return " (held, pen down)";
    case v1::SHAPE_TRIGGER_FOLLOW:
      return " (follows the pen)";
    case v1::SHAPE_TRIGGER_RELEASE:
      return r.hold().adjusted() ? " (released, adjusted by the drag)" : " (released)";
    default:
      return "";
  }
}

void stroke_finished_json(JsonWriter& json, const v1::StrokeFinished& f) {
  json.key("type").string("stroke_finished");
  json.key("stroke_id").integer(static_cast<std::int64_t>(f.stroke().id()));
  json.key("samples").integer(f.stroke().samples_size());
  json.key("duration_us")
      .integer(f.stroke().samples_size() < 2
                   ? 0
                   : f.stroke().samples(f.stroke().samples_size() - 1).time_us() -
                         f.stroke().samples(0).time_us());
  json.key("ink_polygons").integer(f.ink_polygon().polygons_size());
  json.key("not_analysed").string(f.not_analysed());
}

void preview_json(JsonWriter& json, const v1::PreviewCandidates& p) {
  json.key("type").string("preview");
  json.key("stroke_id").integer(static_cast<std::int64_t>(p.stroke_id()));
  json.key("candidates").begin_array();
  for (const auto& c : p.candidates()) write_shape_json(json, c);
  json.end_array();
  if (!p.has_group()) return;
  const v1::PreviewGroup& g = p.group();
  json.key("group").begin_object();
  json.key("shape");
  write_shape_json(json, g.shape());
  write_ids(json, "replaced_stroke_ids", g.replaced_stroke_ids());
  write_ids(json, "supersedes_shape_ids", g.supersedes_shape_ids());
  write_tidy(json, g.tidy());
  json.end_object();
}

void shape_json(JsonWriter& json, const v1::ShapeRecognized& s) {
  json.key("type").string("shape");
  json.key("stroke_id").integer(static_cast<std::int64_t>(s.stroke_id()));
  json.key("shape");
  write_shape_json(json, s.shape());
  json.key("alternatives").begin_array();
  for (const auto& c : s.alternatives()) write_shape_json(json, c);
  json.end_array();
  json.key("compute_us").integer(static_cast<std::int64_t>(s.timings().compute_us()));
  json.key("shape_id").integer(static_cast<std::int64_t>(s.shape_id()));
  write_ids(json, "replaced_stroke_ids", s.replaced_stroke_ids());
  write_ids(json, "supersedes_shape_ids", s.supersedes_shape_ids());
  write_ids(json, "supersedes_sequences", s.supersedes_sequences());
  write_tidy(json, s.tidy());
  json.key("trigger").string(trigger_name(s.trigger()));
  if (s.has_hold()) write_hold_json(json, s.hold());
}

void deconstructed_json(JsonWriter& json, const v1::StrokeDeconstructed& d) {
  const auto& r = d.result();
  json.key("type").string("deconstructed");
  json.key("stroke_id").integer(static_cast<std::int64_t>(d.stroke_id()));
  json.key("not_deconstructed").string(d.not_deconstructed());
  json.key("answer").string(d.not_deconstructed().empty() ? answer_word(r.answer()) : "");
  json.key("pen_radius").number(r.params().radius().approx());
  json.key("tolerance").number(r.params().tolerance().approx());
  json.key("precision").number(r.params().precision().approx());
  json.key("hausdorff_bound").number(r.certificate().hausdorff_bound().approx());
  json.key("solution_vertices")
      .integer(static_cast<std::int64_t>(r.simplification().solution_vertices()));
  json.key("raw_vertices").integer(static_cast<std::int64_t>(r.simplification().raw_vertices()));
  json.key("simplified").boolean(r.simplification().simplified());
  json.key("compute_us").integer(static_cast<std::int64_t>(r.timings().compute_us()));
}

void event_body_json(JsonWriter& json, const v1::LiveEvent& event) {
  switch (event.kind_case()) {
    case v1::LiveEvent::kDeviceAttached:
      json.key("type").string("device_attached");
      json.key("device");
      write_device_json(json, event.device_attached().device());
      break;
    case v1::LiveEvent::kDeviceDetached:
      json.key("type").string("device_detached");
      break;
    case v1::LiveEvent::kStrokeStarted:
      json.key("type").string("stroke_started");
      json.key("stroke_id").integer(static_cast<std::int64_t>(event.stroke_started().stroke_id()));
      break;
    case v1::LiveEvent::kSamples:
      json.key("type").string("samples");
      json.key("stroke_id").integer(static_cast<std::int64_t>(event.samples().stroke_id()));
      json.key("samples").begin_array();
      for (const auto& s : event.samples().samples()) write_sample_json(json, s);
      json.end_array();
      break;
    case v1::LiveEvent::kStrokeFinished:
      stroke_finished_json(json, event.stroke_finished());
      break;
    case v1::LiveEvent::kPreview:
      preview_json(json, event.preview());
      break;
    case v1::LiveEvent::kShape:
      shape_json(json, event.shape());
      break;
    case v1::LiveEvent::kDeconstructed:
      deconstructed_json(json, event.deconstructed());
      break;
    case v1::LiveEvent::kDropped:
      json.key("type").string("dropped");
      json.key("count").integer(static_cast<std::int64_t>(event.dropped().count()));
      json.key("total").integer(static_cast<std::int64_t>(event.dropped().total()));
      break;
    default:
      json.key("type").string("unknown");
      break;
  }
}

} // namespace

std::string event_json(const v1::LiveEvent& event) {
  JsonWriter json;
  json.begin_object();
  json.key("sequence").integer(static_cast<std::int64_t>(event.sequence()));
  json.key("published_us").integer(event.published_us());
  json.key("device_id").string(event.device_id());
  event_body_json(json, event);
  json.end_object();
  return json.str();
}

std::string event_line(const v1::LiveEvent& event) {
  std::string who = "[";
  who += event.device_id().empty() ? std::string("-") : event.device_id();
  who += "] ";
  switch (event.kind_case()) {
    case v1::LiveEvent::kDeviceAttached:
      return who + "attached: " + device_line(event.device_attached().device());
    case v1::LiveEvent::kDeviceDetached:
      return who + "detached";
    case v1::LiveEvent::kStrokeStarted:
      return who + "stroke " + std::to_string(event.stroke_started().stroke_id()) + " started";
    case v1::LiveEvent::kSamples: {
      std::string out = who + std::to_string(event.samples().samples_size()) + " samples";
      if (event.samples().samples_size() > 0) {
        const auto& s = event.samples().samples(event.samples().samples_size() - 1);
        out += ", last x=" + std::to_string(s.x()) + " y=" + std::to_string(s.y()) +
               " pressure=" + std::to_string(s.pressure()) + (s.tip() ? " tip" : "");
      }
      return out;
    }
    case v1::LiveEvent::kStrokeFinished: {
      const auto& f = event.stroke_finished();
      std::string out = who + "stroke " + std::to_string(f.stroke().id()) + " finished, " +
                        std::to_string(f.stroke().samples_size()) + " samples";
      if (!f.not_analysed().empty()) out += " (not analysed: " + f.not_analysed() + ")";
      return out;
    }
    case v1::LiveEvent::kPreview: {
      std::string out = who + "preview of stroke " + std::to_string(event.preview().stroke_id());
      for (const auto& c : event.preview().candidates()) {
        out += ' '; // appended separately: g++ 12 warns falsely (-Wrestrict) on " " + string
        out += shape_kind_name(c.kind());
      }
      if (event.preview().has_group()) {
        const v1::PreviewGroup& g = event.preview().group();
        out += "; with earlier strokes: " + shape_summary(g.shape()) +
               grouping_text(g.replaced_stroke_ids(), g.supersedes_shape_ids(), g.tidy());
      }
      return out;
    }
    case v1::LiveEvent::kShape: {
      const v1::ShapeRecognized& r = event.shape();
      std::string out = who + "stroke " + std::to_string(r.stroke_id());
      if (r.shape_id() != 0) out += " (shape " + std::to_string(r.shape_id()) + ")";
      return out + hold_text(r) + (r.shape().kind() == v1::SHAPE_KIND_NONE ? " is " : " is a ") +
             shape_summary(r.shape()) +
             grouping_text(r.replaced_stroke_ids(), r.supersedes_shape_ids(), r.tidy());
    }
    case v1::LiveEvent::kDeconstructed: {
      const auto& d = event.deconstructed();
      const auto& r = d.result();
      std::string out = who + "stroke " + std::to_string(d.stroke_id()) + " deconstructed: ";
      if (!d.not_deconstructed().empty()) return out + "not done (" + d.not_deconstructed() + ")";
      out += answer_word(r.answer());
      if (r.answer() == v1::ANSWER_YES) {
        out += ", P has " + std::to_string(r.simplification().solution_vertices()) + " vertices";
        if (r.simplification().simplified()) {
          out += " (simplified from " + std::to_string(r.simplification().raw_vertices()) + ")";
        }
        out +=
            ", H(offset(P, r), ink) <= " + millimetres(r.certificate().hausdorff_bound().approx());
      }
      return out + " [r " + millimetres(r.params().radius().approx()) + ", eps " +
             millimetres(r.params().tolerance().approx()) + "]";
    }
    case v1::LiveEvent::kDropped:
      return who + "this client lost " + std::to_string(event.dropped().count()) +
             " events (reading too slowly)";
    default:
      return who + "unknown event";
  }
}

} // namespace penshape::cli
