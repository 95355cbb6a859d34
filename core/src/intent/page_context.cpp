// A stroke's context on its page (page_context.hpp).
#include "page_context.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace penshape::intent {
namespace {

// Writing heights people use, mm: the estimate is kept within them, so that a page of shapes
// alone does not make its shapes "letter-sized".
constexpr double kMinWritingHeight = 1.5;
constexpr double kMaxWritingHeight = 12.0;
constexpr double kMaxGap = 10.0; // writing heights

// The typical writing height: the median height of the smaller half of the strokes (letters
// outnumber shapes on a page of notes; dots do not count).
double writing_height(std::span<const StrokeMeasures> all, std::size_t lo, std::size_t hi) {
  std::vector<const StrokeMeasures*> marks;
  for (std::size_t j = lo; j < hi; ++j) {
    if (!all[j].dot) marks.push_back(&all[j]);
  }
  if (marks.empty()) return kMinWritingHeight;
  std::sort(marks.begin(), marks.end(), [](auto* a, auto* b) { return a->size < b->size; });
  std::vector<double> heights;
  for (std::size_t k = 0; k < (marks.size() + 1) / 2; ++k)
    heights.push_back(marks[k]->box.height());
  std::nth_element(heights.begin(),
                   heights.begin() + static_cast<std::ptrdiff_t>(heights.size() / 2),
                   heights.end());
  return std::clamp(heights[heights.size() / 2], kMinWritingHeight, kMaxWritingHeight);
}

double box_gap(const Box& a, const Box& b) {
  const double dx = std::max({0.0, b.x0 - a.x1, a.x0 - b.x1});
  const double dy = std::max({0.0, b.y0 - a.y1, a.y0 - b.y1});
  return std::hypot(dx, dy);
}

void add_neighbour(const StrokeMeasures& self, const StrokeMeasures& other, Context& c) {
  const double h = c.writing_height;
  const double gap = box_gap(self.box, other.box);
  c.gap = std::min(c.gap, gap / h);
  if (gap <= h) ++c.near;
  const double dx = std::max({0.0, other.box.x0 - self.box.x1, self.box.x0 - other.box.x1});
  if (std::abs(other.box.center_y() - self.box.center_y()) <= 0.75 * h && dx <= 3 * h) {
    ++c.on_line;
  }
  const double cx = 0.5 * (other.box.x0 + other.box.x1);
  const double cy = other.box.center_y();
  if (cx > self.box.x0 && cx < self.box.x1 && cy > self.box.y0 && cy < self.box.y1) ++c.inside;
}

void add_timing(std::span<const StrokeMeasures> all, std::size_t i, Context& c) {
  double pause = kMaxGap;
  if (i > 0 && all[i - 1].timed) pause = std::min(pause, all[i].start_t - all[i - 1].end_t);
  if (i + 1 < all.size() && all[i + 1].timed) {
    pause = std::min(pause, all[i + 1].start_t - all[i].end_t);
  }
  c.pause = std::clamp(pause, 0.0, kMaxGap);
}

} // namespace

Context context_of(std::span<const StrokeMeasures> all, std::size_t i, std::size_t window) {
  const std::size_t lo = i > window ? i - window : 0;
  const std::size_t hi = std::min(all.size(), i + window + 1);
  Context c;
  c.writing_height = writing_height(all, lo, hi);
  c.gap = kMaxGap;
  for (std::size_t j = lo; j < hi; ++j) {
    if (j != i) add_neighbour(all[i], all[j], c);
  }
  int small = 0, seen = 0;
  for (std::size_t j = i > 3 ? i - 3 : 0; j < std::min(all.size(), i + 4); ++j) {
    if (j == i) continue;
    ++seen;
    if (all[j].size <= 2 * c.writing_height) ++small;
  }
  if (seen > 0) c.small_run = static_cast<double>(small) / seen;
  if (all[i].timed) add_timing(all, i, c);
  return c;
}

} // namespace penshape::intent
