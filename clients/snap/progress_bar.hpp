#pragma once
// `penshape snap`'s progress bar on stderr: silent for the first second, then one line redrawn
// in place ("penshape snap: [#####.....] 1234/5678 strokes"), ended with a newline when done.
#include <chrono>
#include <cstddef>

namespace penshape::snap {

class SnapProgress {
 public:
  // Called with strokes done and the total (one call at a time).
  void operator()(std::size_t done, std::size_t total);
  // Ends the line if the bar was shown.
  void finish() const;

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_{};
  bool shown_ = false;
};

} // namespace penshape::snap
