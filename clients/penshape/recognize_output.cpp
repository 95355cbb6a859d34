// Output rows, pictures and the confusion table of `penshape recognize`.
#include "recognize_output.hpp"

#include <cstdio>
#include <filesystem>
#include <set>

#include "json_writer.hpp"
#include "penshape/render/figure.hpp"

namespace penshape::cli {
namespace {

std::string label_for(const FileStroke& s) {
  std::string name = s.label.empty() ? s.name : s.label;
  if (shape_class_from_string(name)) return name;
  while (!name.empty() && std::isdigit(static_cast<unsigned char>(name.back()))) name.pop_back();
  if (name == "triangle" || name == "circle" || name == "rectangle" || name == "arrow") {
    return name;
  }
  return "freeform";
}

bool accepted(const std::string& label, const std::string& got) {
  if (label == got) return true;
  static const std::map<std::string, std::set<std::string>> kFamilies{
      {"circle", {"ellipse"}},
      {"rectangle", {"square", "quadrilateral"}},
      {"square", {"rectangle", "quadrilateral", "diamond"}},
      {"diamond", {"square", "quadrilateral"}},
      {"ellipse", {"circle"}},
  };
  const auto it = kFamilies.find(label);
  return it != kFamilies.end() && it->second.contains(got);
}

void write_point(JsonWriter& json, PointD p) {
  json.begin_array().number(p.x).number(p.y).end_array();
}

void write_params(JsonWriter& json, ShapeClass c, const ShapeParams& p) {
  json.begin_object();
  if (!p.vertices.empty()) {
    json.key("vertices").begin_array();
    for (const PointD& v : p.vertices) write_point(json, v);
    json.end_array();
  }
  if (c == ShapeClass::kFreeform) return void(json.end_object());
  json.key("center");
  write_point(json, p.center);
  if (p.radius_x > 0) json.key("radius_x").number(p.radius_x);
  if (p.radius_y > 0) json.key("radius_y").number(p.radius_y);
  json.key("rotation").number(p.rotation);
  if (c == ShapeClass::kArc) {
    json.key("start_angle").number(p.start_angle);
    json.key("sweep_angle").number(p.sweep_angle);
  }
  if (c == ShapeClass::kArrow || c == ShapeClass::kDoubleArrow) {
    // vertices: tail, tip, the tip's barbs (then the tail's barbs of a double arrow)
    json.key("head_angle").number(p.head_angle);
    json.key("shaft_bulge").number(p.shaft_bulge);
    // A bent shaft's interior vertices from tail to tip (empty: straight or curved).
    json.key("shaft_bends").begin_array();
    for (const PointD& b : p.shaft_bends) write_point(json, b);
    json.end_array();
    // A shaft that stops short of the tip ends here (absent: it runs to the tip).
    if (p.shaft_end) {
      json.key("shaft_end");
      write_point(json, *p.shaft_end);
    }
  }
  json.end_object();
}

void write_certificate(JsonWriter& json, const Certificate& c) {
  json.begin_object();
  json.key("certified").boolean(c.certified);
  json.key("bound").number(c.bound);
  json.key("epsilon").number(c.epsilon);
  json.key("pen_radius").number(c.pen_radius);
  json.key("sample_spacing").number(c.sample_spacing);
  json.key("method").string(c.method);
  json.end_object();
}

// The outline of a shape that is not freeform (a dot with no pen size has none).
render::ShapeOutline outline_shape(const Recognition& r) {
  using Outline = render::ShapeOutline;
  const ShapeParams& p = r.params;
  switch (r.shape) {
    case ShapeClass::kCircle:
      return Outline::circle(p.center, p.radius_x);
    case ShapeClass::kEllipse:
      return Outline::ellipse(p.center, p.radius_x, p.radius_y, p.rotation);
    case ShapeClass::kArc:
      return Outline::arc(p.center, p.radius_x, p.start_angle, p.sweep_angle);
    case ShapeClass::kDot: // drawn as a disk of the pen's radius
      return Outline::circle(p.center, r.pen_radius);
    case ShapeClass::kSegment:
    case ShapeClass::kPolyline:
      return {.kind = Outline::Kind::kPolyline, .vertices = p.vertices};
    case ShapeClass::kArrow:
    case ShapeClass::kDoubleArrow: // the clean path: shaft, barbs
      return {.kind = Outline::Kind::kPolyline, .vertices = r.clean};
    default:
      return {.kind = Outline::Kind::kPolygon, .vertices = p.vertices};
  }
}

std::optional<render::ShapeOutline> outline_of(const Recognition& r) {
  if (r.shape == ShapeClass::kFreeform) return std::nullopt;
  if (r.shape == ShapeClass::kDot && !(r.pen_radius > 0)) return std::nullopt;
  render::ShapeOutline o = outline_shape(r);
  o.label = to_string(r.shape);
  return o;
}

// The picture of one answer (input units as "mm": the picture is scale-free).
render::StrokeFigure figure_of(const RecognizeRow& row) {
  const Recognition& r = row.shape.recognition;
  render::StrokeFigure fig;
  for (const FileStroke* s : row.strokes) {
    fig.stroke_starts.push_back(fig.samples.size());
    for (const auto& p : s->points) fig.samples.push_back({p.x, p.y});
  }
  fig.pen_radius = r.pen_radius;
  fig.tolerance = r.certificate.certified ? r.epsilon : 0.0;
  const FileStroke& first = *row.strokes.front();
  fig.caption = (first.name.empty() ? first.file : first.name) + ": " + to_string(r.shape);
  if (row.strokes.size() > 1)
    fig.caption += " (" + std::to_string(row.strokes.size()) + " strokes)";
  fig.shape = outline_of(r);
  return fig;
}

void write_json_row(const RecognizeRow& row, const std::string* label) {
  const Recognition& r = row.shape.recognition;
  const FileStroke& first = *row.strokes.front();
  JsonWriter json;
  json.begin_object();
  json.key("file").string(first.file);
  json.key("line").integer(static_cast<std::int64_t>(first.line));
  json.key("lines").begin_array();
  for (const FileStroke* s : row.strokes) json.integer(static_cast<std::int64_t>(s->line));
  json.end_array();
  json.key("name").string(first.name);
  if (label) json.key("label").string(*label);
  json.key("class").string(to_string(r.shape));
  json.key("intent").string(std::string(to_string(row.intent.intent)));
  json.key("writing_score").number(row.intent.writing_score);
  json.key("confidence").number(r.confidence);
  json.key("bound").number(r.certificate.bound);
  json.key("rms").number(r.rms);
  json.key("params");
  write_params(json, r.shape, r.params);
  json.key("tidy").begin_array();
  for (const std::string& t : row.shape.tidy) json.string(t);
  json.end_array();
  json.key("alternatives").begin_array();
  for (const Candidate& c : r.alternatives) {
    json.begin_object();
    json.key("class").string(to_string(c.shape));
    json.key("certified").boolean(c.certificate.certified);
    json.key("bound").number(c.certificate.bound);
    json.key("rms").number(c.rms);
    if (!c.params.vertices.empty())
      json.key("corners").number(static_cast<double>(c.params.vertices.size()));
    if (!c.rejected.empty()) json.key("rejected").string(c.rejected);
    json.end_object();
  }
  json.end_array();
  json.key("certified").boolean(r.certificate.certified);
  json.key("certificate_method").string(r.certificate.method);
  json.key("certificate");
  write_certificate(json, r.certificate);
  json.key("seconds").number(row.seconds);
  json.end_object();
  std::puts(json.str().c_str());
}

void write_text_row(const RecognizeRow& row, const std::string* label) {
  const Recognition& r = row.shape.recognition;
  const FileStroke& first = *row.strokes.front();
  const std::string got = to_string(r.shape);
  std::printf("%s:%zu", first.file.c_str(), first.line);
  for (std::size_t i = 1; i < row.strokes.size(); ++i) std::printf(",%zu", row.strokes[i]->line);
  std::printf(" %s -> %s", first.name.c_str(), got.c_str());
  if (row.intent.intent == Intent::kWriting) std::printf(" (writing)");
  if (r.certificate.certified) {
    std::printf(" (confidence %.2f, bound %.3g <= eps %.3g)", r.confidence, r.certificate.bound,
                r.epsilon);
  }
  if (!row.shape.tidy.empty()) {
    std::printf(" tidy");
    for (const std::string& t : row.shape.tidy) std::printf(" %s", t.c_str());
  }
  if (label) std::printf(" [label %s%s]", label->c_str(), accepted(*label, got) ? "" : ", WRONG");
  std::printf(" %.3f ms\n", row.seconds * 1e3);
}

} // namespace

void RecognizeReport::add(const RecognizeRow& row) {
  const FileStroke& first = *row.strokes.front();
  if (options_.svg_dir) {
    const std::string name = std::filesystem::path(first.file).stem().string() + "-" +
                             std::to_string(first.line) + ".svg";
    render::write_svg_file((std::filesystem::path(*options_.svg_dir) / name).string(),
                           render::stroke_svg(figure_of(row)));
  }
  const std::string got = to_string(row.shape.recognition.shape);
  const std::string label = options_.labels ? label_for(first) : "";
  ++answers_;
  if (options_.labels) {
    ++confusion_[label][got];
    if (accepted(label, got)) ++correct_;
  }
  if (options_.json) {
    write_json_row(row, options_.labels ? &label : nullptr);
  } else {
    write_text_row(row, options_.labels ? &label : nullptr);
  }
}

void RecognizeReport::finish() const {
  if (!options_.labels) return;
  if (options_.json) {
    JsonWriter json;
    json.begin_object().key("summary").begin_object();
    json.key("strokes").integer(static_cast<std::int64_t>(answers_));
    json.key("correct").integer(static_cast<std::int64_t>(correct_));
    json.key("confusion").begin_object();
    for (const auto& [label, row] : confusion_) {
      json.key(label).begin_object();
      for (const auto& [got, n] : row) json.key(got).integer(static_cast<std::int64_t>(n));
      json.end_object();
    }
    json.end_object().end_object().end_object();
    std::puts(json.str().c_str());
    return;
  }
  std::set<std::string> columns;
  for (const auto& [label, row] : confusion_) {
    for (const auto& [got, n] : row) columns.insert(got);
  }
  std::printf("\n%-12s", "label\\class");
  for (const auto& c : columns) std::printf(" %10.10s", c.c_str());
  std::printf(" %8s\n", "correct");
  for (const auto& [label, row] : confusion_) {
    std::size_t total = 0, ok = 0;
    std::printf("%-12s", label.c_str());
    for (const auto& c : columns) {
      const auto it = row.find(c);
      const std::size_t n = it == row.end() ? 0 : it->second;
      total += n;
      if (accepted(label, c)) ok += n;
      std::printf(" %10zu", n);
    }
    std::printf(" %7.1f%%\n",
                total ? 100.0 * static_cast<double>(ok) / static_cast<double>(total) : 0.0);
  }
  std::printf(
      "overall: %zu / %zu correct (%.1f%%)\n", correct_, answers_,
      answers_ ? 100.0 * static_cast<double>(correct_) / static_cast<double>(answers_) : 0.0);
}

} // namespace penshape::cli
