#pragma once
// A progress bar for long offline work (radius suggestions, large directories) on stderr.
// It draws only on a terminal: when the stream is not a TTY (a log, a pipe, a test) it stays
// silent, so scripted output is never cluttered. Redraws at most 10 times a second.
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace penshape::render {

// One line: "label [#########.........]  45/100  12.3 s, about 15 s left". With total == 0 the
// amount is unknown: "label  45 done  12.3 s". Width is the bar's inner width in characters.
std::string progress_line(const std::string& label, std::size_t done, std::size_t total,
                          std::chrono::duration<double> elapsed, std::size_t width = 30);

class ProgressBar {
 public:
  enum class Mode { kAuto, kAlways, kNever }; // kAuto: draw only when `out` is a terminal

  ProgressBar(std::string label, std::size_t total, std::FILE* out = stderr,
              Mode mode = Mode::kAuto);
  ~ProgressBar(); // finish()
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void update(std::size_t done);   // redraws when enough time has passed
  void advance(std::size_t n = 1); // update(done + n)
  void finish();                   // draws the final state and ends the line (idempotent)
  [[nodiscard]] bool drawing() const { return enabled_; }

 private:
  void draw();
  std::string label_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::FILE* out_;
  bool enabled_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

} // namespace penshape::render
