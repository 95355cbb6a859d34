#pragma once
// The pen path as the live recognizer keeps it: every distinct position (for pen-up), its
// bounding box, and a thinned copy for live fits (live_recognizer.hpp, "Refit policy").
#include <cstddef>
#include <vector>

#include "penshape/core/recognize.hpp"
#include "recognize/fitting/geometry.hpp"

namespace penshape::recognize_detail {

class LivePath {
 public:
  explicit LivePath(double thin_fraction = 0.0) : thin_fraction_(thin_fraction) {}

  // Adds a position; false for a repeat of the last one (ignored). kept_grew() then tells
  // whether it joined the thinned path (at least thin_fraction * size from the last kept one).
  bool add(PointD p);
  [[nodiscard]] bool kept_grew() const { return kept_grew_; }

  [[nodiscard]] const std::vector<PointD>& points() const { return points_; }
  [[nodiscard]] const std::vector<PointD>& kept() const { return kept_; }
  [[nodiscard]] PointD lo() const { return lo_; }
  [[nodiscard]] PointD hi() const { return hi_; }
  [[nodiscard]] double size() const { return distance(lo_, hi_); }
  [[nodiscard]] double magnitude() const; // largest |x|, |y| so far
  [[nodiscard]] ToleranceChoice tolerance(const RecognizerConfig& config) const;

  // The kept points and the latest position, evenly strided down to at most `cap` points
  // (ends kept).
  [[nodiscard]] std::vector<PointD> fit_path(std::size_t cap) const;

 private:
  double thin_fraction_;
  std::vector<PointD> points_;
  std::vector<PointD> kept_;
  PointD lo_, hi_;
  bool kept_grew_ = false;
};

} // namespace penshape::recognize_detail
