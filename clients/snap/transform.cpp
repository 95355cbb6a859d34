// Parsing and composing SVG transform lists (SVG 1.1, section 7.6).
#include "transform.hpp"

#include <cctype>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "number_scanner.hpp"

namespace penshape::snap {
namespace {

Affine translate(double x, double y) { return {1, 0, 0, 1, x, y}; }

Affine rotate_deg(double deg) {
  const double t = deg * std::numbers::pi / 180.0;
  return {std::cos(t), std::sin(t), -std::sin(t), std::cos(t), 0, 0};
}

Affine one(const std::string& name, const std::vector<double>& v) {
  const auto need = [&](std::size_t lo, std::size_t hi) {
    if (v.size() < lo || v.size() > hi) {
      throw TransformError(name + "() takes " + std::to_string(lo) +
                           (lo == hi ? "" : " to " + std::to_string(hi)) + " numbers, got " +
                           std::to_string(v.size()));
    }
  };
  const double deg2rad = std::numbers::pi / 180.0;
  if (name == "matrix") {
    need(6, 6);
    return {v[0], v[1], v[2], v[3], v[4], v[5]};
  }
  if (name == "translate") {
    need(1, 2);
    return translate(v[0], v.size() > 1 ? v[1] : 0.0);
  }
  if (name == "scale") {
    need(1, 2);
    return {v[0], 0, 0, v.size() > 1 ? v[1] : v[0], 0, 0};
  }
  if (name == "rotate") {
    if (v.size() == 2) need(1, 1); // rotate(a, cx) is not SVG
    need(1, 3);
    if (v.size() == 1) return rotate_deg(v[0]);
    return translate(v[1], v[2]).then_inner(rotate_deg(v[0])).then_inner(translate(-v[1], -v[2]));
  }
  if (name == "skewX") {
    need(1, 1);
    return {1, 0, std::tan(v[0] * deg2rad), 1, 0, 0};
  }
  if (name == "skewY") {
    need(1, 1);
    return {1, std::tan(v[0] * deg2rad), 0, 1, 0, 0};
  }
  throw TransformError("unknown transform '" + name + "'");
}

} // namespace

Affine Affine::then_inner(const Affine& m) const {
  return {a * m.a + c * m.b, b * m.a + d * m.b,     a * m.c + c * m.d,
          b * m.c + d * m.d, a * m.e + c * m.f + e, b * m.e + d * m.f + f};
}

bool Affine::invertible() const {
  const double det = a * d - b * c;
  return std::isfinite(det) && std::abs(det) > 1e-12 * (a * a + b * b + c * c + d * d);
}

Affine Affine::inverse() const {
  const double det = a * d - b * c;
  const Affine lin{d / det, -b / det, -c / det, a / det, 0, 0};
  const PointD t = lin.apply({e, f});
  return {lin.a, lin.b, lin.c, lin.d, -t.x, -t.y};
}

bool Affine::is_similarity() const {
  // Columns (a, b) and (c, d) orthogonal and of equal length.
  const double n1 = a * a + b * b, n2 = c * c + d * d;
  const double tol = 1e-9 * std::max(n1, n2);
  return std::abs(n1 - n2) <= tol && std::abs(a * c + b * d) <= tol && n1 > 0;
}

double Affine::scale() const { return std::sqrt(std::abs(a * d - b * c)); }

Affine parse_transform(std::string_view text) {
  NumberScanner in(text);
  Affine total;
  for (in.skip_separators(); !in.done(); in.skip_separators()) {
    std::string name;
    while (!in.done() && std::isalpha(static_cast<unsigned char>(in.peek()))) name += in.take();
    if (name.empty()) throw TransformError("expected a transform name at offset " + in.where());
    in.skip_spaces();
    if (in.done() || in.take() != '(') throw TransformError("expected '(' after " + name);
    std::vector<double> values;
    for (in.skip_separators(); !in.done() && in.peek() != ')'; in.skip_separators()) {
      const auto v = in.number();
      if (!v) throw TransformError("bad number in " + name + "() at offset " + in.where());
      values.push_back(*v);
    }
    if (in.done()) throw TransformError("missing ')' after " + name + "(");
    in.take();
    total = total.then_inner(one(name, values));
  }
  return total;
}

} // namespace penshape::snap
