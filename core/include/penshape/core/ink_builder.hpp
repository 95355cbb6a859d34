#pragma once
// The ink polygon Q of a stroke built while it is drawn (the daemon's pen-up path): Q is made of
// chunks of the stroke (ink.hpp), and each chunk the samples so far complete can be built before
// pen-up, so that a pen-up leaves only its last chunk and Q's final union to do. polygon() gives
// ink_polygon(samples, options) bit for bit, whatever was built before (chunks built under a
// plan the whole stroke changes, e.g. a finer disk for a wider pressure radius, are rebuilt).
// Not thread-safe: one thread at a time (the daemon holds a lock around it).
#include <cstddef>
#include <memory>
#include <vector>

#include "penshape/core/ink.hpp"

namespace penshape {

namespace ink_detail {
struct ChunkPieces;
struct Reach;
class FedUnion;
} // namespace ink_detail

class InkBuilder {
 public:
  explicit InkBuilder(const InkOptions& options);
  ~InkBuilder();
  InkBuilder(InkBuilder&&) noexcept;
  InkBuilder& operator=(InkBuilder&&) noexcept;
  InkBuilder(const InkBuilder&) = delete;
  InkBuilder& operator=(const InkBuilder&) = delete;

  // Appends samples of the stroke in progress (in mm, as ink_samples() gives them).
  void add(const std::vector<InkSample>& samples);
  // Builds the next chunk the samples so far complete (a chunk reads kChunkSegments + 1 samples
  // from a fixed start, whatever comes after them); false when there is none, or when the
  // samples so far are invalid (polygon() then throws ink_polygon's error).
  bool build_next();
  // Q of `samples` (the whole stroke): the chunks built for a prefix of them are reused, the rest
  // built here. Throws as ink_polygon(samples, options) does. The first call also takes the final
  // union's pieces given while the chunks were built, when they all are reused; later calls
  // build the union whole (same Q, more work).
  [[nodiscard]] InkPolygon polygon(const std::vector<InkSample>& samples);

  [[nodiscard]] std::size_t samples() const { return samples_.size(); }
  [[nodiscard]] std::size_t built_chunks() const;

 private:
  InkOptions options_;
  std::vector<InkSample> samples_;
  std::vector<ink_detail::ChunkPieces> chunks_;
  std::unique_ptr<ink_detail::Reach> reach_; // of samples_[0, reached_), checked
  std::size_t reached_ = 0;
  std::unique_ptr<ink_detail::FedUnion> fed_; // Q's final union, given chunks_[0, fed_chunks_)
  std::size_t fed_chunks_ = 0;
  bool invalid_ = false;
};

} // namespace penshape
