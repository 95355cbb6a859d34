#pragma once
// SVG affine transforms: the `transform` attribute parsed into a matrix, composed along the
// element tree, applied to points. Part of the one tested place for SVG geometry (with
// path_data.hpp).
#include <stdexcept>
#include <string_view>

#include "penshape/core/polygon_set.hpp" // PointD

namespace penshape::snap {

// x' = a x + c y + e, y' = b x + d y + f (the SVG matrix(a b c d e f)).
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

  [[nodiscard]] PointD apply(PointD p) const {
    return {a * p.x + c * p.y + e, b * p.x + d * p.y + f};
  }
  // This after `inner`: (this * inner)(p) = this(inner(p)).
  [[nodiscard]] Affine then_inner(const Affine& inner) const;
  [[nodiscard]] Affine inverse() const; // precondition: invertible()
  [[nodiscard]] bool invertible() const;
  // A rotation, reflection, uniform scale and translation (circles stay circles), within 1e-9.
  [[nodiscard]] bool is_similarity() const;
  // sqrt(|det|): how lengths scale (exact for similarities).
  [[nodiscard]] double scale() const;
};

struct TransformError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The transform attribute's list (matrix, translate, scale, rotate with optional centre, skewX,
// skewY; commas or spaces), composed left to right as SVG does. Throws TransformError naming the
// problem.
Affine parse_transform(std::string_view text);

} // namespace penshape::snap
