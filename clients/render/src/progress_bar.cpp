#include "penshape/render/progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace penshape::render {
namespace {

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, s < 10 ? "%.1f s" : "%.0f s", s);
  return buf;
}

constexpr std::chrono::milliseconds kRedrawInterval{100};

} // namespace

std::string progress_line(const std::string& label, std::size_t done, std::size_t total,
                          std::chrono::duration<double> elapsed, std::size_t width) {
  const double t = elapsed.count();
  if (total == 0) return label + "  " + std::to_string(done) + " done  " + seconds(t);
  done = std::min(done, total);
  const double fraction = static_cast<double>(done) / static_cast<double>(total);
  const auto filled = static_cast<std::size_t>(fraction * static_cast<double>(width));
  std::string line = label + " [" + std::string(filled, '#') + std::string(width - filled, '.') +
                     "]  " + std::to_string(done) + "/" + std::to_string(total) + "  " + seconds(t);
  if (done > 0 && done < total) {
    line += ", about " + seconds(t / fraction - t) + " left";
  }
  return line;
}

ProgressBar::ProgressBar(std::string label, std::size_t total, std::FILE* out, Mode mode)
    : label_(std::move(label)),
      total_(total),
      out_(out),
      enabled_(mode == Mode::kAlways ||
               (mode == Mode::kAuto && out != nullptr && ::isatty(::fileno(out)) == 1)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_ - kRedrawInterval) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(std::size_t done) {
  done_ = done;
  if (!enabled_ || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  draw();
}

void ProgressBar::advance(std::size_t n) { update(done_ + n); }

void ProgressBar::draw() {
  const std::string line =
      progress_line(label_, done_, total_, std::chrono::steady_clock::now() - start_);
  // "\r" and clear-to-end-of-line: the bar redraws in place.
  std::fprintf(out_, "\r%s\x1b[K", line.c_str());
  std::fflush(out_);
}

void ProgressBar::finish() {
  if (finished_) return;
  finished_ = true;
  if (!enabled_) return;
  draw();
  std::fputc('\n', out_);
  std::fflush(out_);
}

} // namespace penshape::render
