// The ink polygon of live strokes built while the pen is down (ink_ahead.hpp).
#include "ink_ahead.hpp"

#include <iterator>

namespace penshape::daemon {

void InkAhead::feed(const Stroke& partial, const CancelHook& cancel) {
  std::lock_guard lock(mutex_);
  if (fed_ < partial.samples.size()) {
    Stroke fresh; // only the samples not seen yet, converted one by one as ink_samples() does
    fresh.tablet = partial.tablet;
    fresh.samples.assign(partial.samples.begin() + static_cast<std::ptrdiff_t>(fed_),
                         partial.samples.end());
    builder_.add(ink_samples(fresh, options_));
    fed_ = partial.samples.size();
  }
  while (!(cancel && cancel()) && builder_.build_next()) {
  }
}

InkPolygon InkAhead::polygon(const std::vector<InkSample>& samples, const InkOptions& options) {
  if (options != options_) return ink_polygon(samples, options); // the pen changed meanwhile
  std::lock_guard lock(mutex_);
  return builder_.polygon(samples);
}

std::size_t InkAhead::built_chunks() {
  std::lock_guard lock(mutex_);
  return builder_.built_chunks();
}

std::shared_ptr<InkAhead> InkAheadTable::open(std::uint64_t stroke_id, const InkOptions& options) {
  std::lock_guard lock(mutex_);
  auto it = strokes_.find(stroke_id);
  if (it == strokes_.end()) {
    // Strokes seldom overlap: an entry a stroke never finished (a device reset) goes soon.
    if (strokes_.size() > 64) strokes_.clear();
    it = strokes_.emplace(stroke_id, std::make_shared<InkAhead>(options)).first;
  }
  return it->second;
}

std::shared_ptr<InkAhead> InkAheadTable::find(std::uint64_t stroke_id) {
  std::lock_guard lock(mutex_);
  const auto it = strokes_.find(stroke_id);
  return it == strokes_.end() ? nullptr : it->second;
}

void InkAheadTable::forget(std::uint64_t stroke_id) {
  std::lock_guard lock(mutex_);
  strokes_.erase(stroke_id);
}

} // namespace penshape::daemon
