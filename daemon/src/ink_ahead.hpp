#pragma once
// The ink polygon Q of live strokes built ahead while the pen is down (core's InkBuilder), so a
// pen-up has only Q's last chunk and its final union left to do. Q comes out the same, bit for
// bit, as core's ink_polygon() of the whole stroke: work ahead is only ever reused, never trusted
// (samples compared, options compared, anything else rebuilt).
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "penshape/core/base.hpp"
#include "penshape/core/ink.hpp"
#include "penshape/core/ink_builder.hpp"
#include "penshape/types/stroke.hpp"

namespace penshape::daemon {

// One stroke's Q in progress; thread-safe (one lock: a pen-up waits for the chunk being built).
class InkAhead {
 public:
  explicit InkAhead(const InkOptions& options) : options_(options), builder_(options) {}
  // Takes the samples of `partial` (the stroke so far) not seen yet and builds the chunks they
  // complete, until `cancel` asks to stop. Samples are converted as ink_samples() does.
  void feed(const Stroke& partial, const CancelHook& cancel);
  // Q of the whole stroke's `samples` drawn with `options`: ink_polygon(samples, options).
  InkPolygon polygon(const std::vector<InkSample>& samples, const InkOptions& options);
  [[nodiscard]] std::size_t built_chunks();

 private:
  std::mutex mutex_;
  InkOptions options_;
  InkBuilder builder_;
  std::size_t fed_ = 0; // samples of the stroke taken
};

// The strokes in progress, by stroke id.
class InkAheadTable {
 public:
  // The stroke's entry, made with `options` when there is none.
  std::shared_ptr<InkAhead> open(std::uint64_t stroke_id, const InkOptions& options);
  // The stroke's entry, or null.
  std::shared_ptr<InkAhead> find(std::uint64_t stroke_id);
  void forget(std::uint64_t stroke_id);

 private:
  std::mutex mutex_;
  std::map<std::uint64_t, std::shared_ptr<InkAhead>> strokes_;
};

} // namespace penshape::daemon
