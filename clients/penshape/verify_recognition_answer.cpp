// recognition_from_json(): the fields of a recognition answer (verify_recognition_answer.hpp).
#include "verify_recognition_answer.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "geometry_cli.hpp"
#include "verify_answer.hpp"

namespace penshape::cli {
namespace {

double number(const JsonValue& v, const std::string& path) {
  if (v.kind != JsonValue::Kind::kNumber) throw InputError("field '" + path + "' must be a number");
  double out = 0.0;
  const char* end = v.text.data() + v.text.size();
  const auto res = std::from_chars(v.text.data(), end, out);
  if (res.ec != std::errc() || res.ptr != end || !std::isfinite(out)) {
    throw InputError("field '" + path + "' is not a finite number");
  }
  return out;
}

double optional_number(const JsonValue& v, std::string_view key, const std::string& path) {
  const JsonValue* f = v.find(key);
  return f ? number(*f, path + std::string(key)) : 0.0;
}

PointD point(const JsonValue& v, const std::string& path) {
  if (v.kind != JsonValue::Kind::kArray || v.items.size() != 2) {
    throw InputError("field '" + path + "' must be [x, y]");
  }
  return {number(v.items[0], path + "[0]"), number(v.items[1], path + "[1]")};
}

std::size_t line_number(const JsonValue& v, const std::string& path) {
  const double d = number(v, path);
  if (d < 1 || d != std::floor(d) || d > 1e15)
    throw InputError("field '" + path + "' must be a line number");
  return static_cast<std::size_t>(d);
}

ShapeParams params_of(const JsonValue& p) {
  if (p.kind != JsonValue::Kind::kObject) throw InputError("field 'params' must be an object");
  ShapeParams out;
  if (const JsonValue* v = p.find("vertices")) {
    if (v->kind != JsonValue::Kind::kArray)
      throw InputError("field 'params.vertices' must be a list");
    for (std::size_t i = 0; i < v->items.size(); ++i) {
      out.vertices.push_back(point(v->items[i], "params.vertices[" + std::to_string(i) + "]"));
    }
  }
  if (const JsonValue* c = p.find("center")) out.center = point(*c, "params.center");
  out.radius_x = optional_number(p, "radius_x", "params.");
  out.radius_y = optional_number(p, "radius_y", "params.");
  out.rotation = optional_number(p, "rotation", "params.");
  out.start_angle = optional_number(p, "start_angle", "params.");
  out.sweep_angle = optional_number(p, "sweep_angle", "params.");
  out.head_angle = optional_number(p, "head_angle", "params.");
  out.shaft_bulge = optional_number(p, "shaft_bulge", "params.");
  if (const JsonValue* b = p.find("shaft_bends")) {
    if (b->kind != JsonValue::Kind::kArray)
      throw InputError("field 'params.shaft_bends' must be a list");
    for (std::size_t i = 0; i < b->items.size(); ++i) {
      out.shaft_bends.push_back(
          point(b->items[i], "params.shaft_bends[" + std::to_string(i) + "]"));
    }
  }
  if (const JsonValue* e = p.find("shaft_end")) out.shaft_end = point(*e, "params.shaft_end");
  return out;
}

} // namespace

bool is_recognition_answer(const JsonValue& v) {
  return v.kind == JsonValue::Kind::kObject && v.find("class") != nullptr;
}

bool is_recognition_summary(const JsonValue& v) {
  return v.kind == JsonValue::Kind::kObject && v.find("summary") != nullptr &&
         v.members.size() == 1;
}

RecognitionAnswer recognition_from_json(const JsonValue& answer) {
  RecognitionAnswer out;
  const JsonValue& cls = answer_field(answer, "class", "");
  if (cls.kind != JsonValue::Kind::kString) throw InputError("field 'class' must be a string");
  const auto shape = shape_class_from_string(cls.text);
  if (!shape) throw InputError("field 'class': unknown class '" + cls.text + "'");
  out.claim.shape = *shape;
  if (const JsonValue* lines = answer.find("lines")) {
    if (lines->kind != JsonValue::Kind::kArray || lines->items.empty()) {
      throw InputError("field 'lines' must be a non-empty list");
    }
    for (std::size_t i = 0; i < lines->items.size(); ++i) {
      out.lines.push_back(line_number(lines->items[i], "lines[" + std::to_string(i) + "]"));
    }
  } else {
    out.lines.push_back(line_number(answer_field(answer, "line", ""), "line"));
  }
  if (out.claim.shape == ShapeClass::kFreeform) return out; // claims nothing
  out.claim.params = params_of(answer_field(answer, "params", ""));
  const JsonValue& cert = answer_field(answer, "certificate", "");
  out.claim.epsilon = number(answer_field(cert, "epsilon", "certificate."), "certificate.epsilon");
  out.claim.pen_radius =
      number(answer_field(cert, "pen_radius", "certificate."), "certificate.pen_radius");
  // The claim is H <= bound <= eps: the bound is checked, not only eps.
  out.claim.bound = number(answer_field(cert, "bound", "certificate."), "certificate.bound");
  return out;
}

} // namespace penshape::cli
