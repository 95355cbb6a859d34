// The progress bar of `penshape snap` (see progress_bar.hpp): redrawn at most ten times a second.
#include "progress_bar.hpp"

#include <cstdio>
#include <string>

namespace penshape::snap {

void SnapProgress::operator()(std::size_t done, std::size_t total) {
  using namespace std::chrono_literals;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < 1s || (now - last_ < 100ms && done < total) || total == 0) return;
  last_ = now;
  constexpr std::size_t kWidth = 30;
  const std::size_t filled = done * kWidth / total;
  const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '.');
  std::fprintf(stderr, "\rpenshape snap: [%s] %zu/%zu strokes", bar.c_str(), done, total);
  std::fflush(stderr);
  shown_ = true;
}

void SnapProgress::finish() const {
  if (shown_) std::fputc('\n', stderr);
}

} // namespace penshape::snap
