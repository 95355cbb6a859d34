// claim_from_json(): the fields of a deconstruction answer (verify_answer.hpp).
#include "verify_answer.hpp"

#include "geometry_cli.hpp"
#include "penshape/core/polygon_io.hpp"

namespace penshape::cli {
namespace {

Rational rational(const JsonValue& v, const std::string& path) {
  if (v.kind != JsonValue::Kind::kNumber && v.kind != JsonValue::Kind::kString) {
    throw InputError("field '" + path + "' must be a number");
  }
  try {
    return parse_rational(v.text);
  } catch (const InvalidInput& e) {
    throw InputError("field '" + path + "': " + e.what());
  }
}

ExactPoint point(const JsonValue& v, const std::string& path) {
  if (v.kind != JsonValue::Kind::kArray || v.items.size() != 2) {
    throw InputError("field '" + path + "' must be [x, y]");
  }
  return {rational(v.items[0], path + "[0]"), rational(v.items[1], path + "[1]")};
}

Ring ring(const JsonValue& v, const std::string& path) {
  if (v.kind != JsonValue::Kind::kArray) throw InputError("field '" + path + "' must be a list");
  Ring out;
  for (std::size_t i = 0; i < v.items.size(); ++i) {
    out.push_back(point(v.items[i], path + "[" + std::to_string(i) + "]"));
  }
  return out;
}

PolygonSet polygon_set(const JsonValue& v, const std::string& path) {
  if (v.kind != JsonValue::Kind::kArray) throw InputError("field '" + path + "' must be a list");
  PolygonSet out;
  for (std::size_t k = 0; k < v.items.size(); ++k) {
    const std::string at = path + "[" + std::to_string(k) + "].";
    PolygonWithHoles p;
    p.outer = ring(answer_field(v.items[k], "outer", at), at + "outer");
    const JsonValue& holes = answer_field(v.items[k], "holes", at);
    if (holes.kind != JsonValue::Kind::kArray)
      throw InputError("field '" + at + "holes' must be a list");
    for (std::size_t h = 0; h < holes.items.size(); ++h) {
      p.holes.push_back(ring(holes.items[h], at + "holes[" + std::to_string(h) + "]"));
    }
    out.polygons.push_back(std::move(p));
  }
  return out;
}

Answer answer_of(const JsonValue& v) {
  if (v.kind == JsonValue::Kind::kString) {
    if (v.text == "YES") return Answer::kYes;
    if (v.text == "NO") return Answer::kNo;
    if (v.text == "UNDECIDED") return Answer::kUndecided;
  }
  throw InputError("field 'answer' must be YES, NO or UNDECIDED");
}

} // namespace

const JsonValue& answer_field(const JsonValue& v, std::string_view key, const std::string& path) {
  const JsonValue* f = v.find(key);
  if (f == nullptr) throw InputError("missing field '" + path + std::string(key) + "'");
  return *f;
}

DeconstructionClaim claim_from_json(const JsonValue& answer) {
  if (answer.kind != JsonValue::Kind::kObject) throw InputError("an answer must be a JSON object");
  if (answer.find("answer") == nullptr || answer.find("params") == nullptr) {
    throw InputError("not a deconstruct --json answer (no 'answer' and 'params' fields)");
  }
  DeconstructionClaim c;
  c.answer = answer_of(answer_field(answer, "answer", ""));
  const JsonValue* exact_fields = answer.find("exact");
  // Exact values when the answer carries them, else the printed decimals, read exactly.
  const JsonValue& params =
      exact_fields != nullptr ? *exact_fields : answer_field(answer, "params", "");
  const std::string at = exact_fields != nullptr ? "exact." : "params.";
  c.radius = rational(answer_field(params, "radius", at), at + "radius");
  c.tolerance = rational(answer_field(params, "tolerance", at), at + "tolerance");
  c.precision = rational(answer_field(params, "precision", at), at + "precision");
  if (c.answer == Answer::kYes) {
    const JsonValue* wkt = exact_fields != nullptr ? exact_fields->find("solution") : nullptr;
    if (wkt != nullptr && wkt->kind == JsonValue::Kind::kString) {
      try {
        c.solution = read_wkt(wkt->text);
      } catch (const InvalidInput& e) {
        throw InputError(std::string("field 'exact.solution': ") + e.what());
      }
    } else {
      c.solution = polygon_set(answer_field(answer, "solution", ""), "solution");
    }
  }
  if (c.answer == Answer::kNo) {
    const JsonValue* w = exact_fields != nullptr ? exact_fields->find("no_witness") : nullptr;
    if (w != nullptr) {
      c.no_witness = point(*w, "exact.no_witness");
    } else if (const JsonValue* wd = answer.find("no_witness");
               wd != nullptr && wd->kind != JsonValue::Kind::kNull) {
      c.no_witness = point(*wd, "no_witness");
    }
  }
  return c;
}

} // namespace penshape::cli
