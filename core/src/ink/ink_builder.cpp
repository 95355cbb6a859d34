// InkBuilder: the ink polygon's chunks built while the stroke is drawn (ink_builder.hpp).
#include "penshape/core/ink_builder.hpp"

#include <algorithm>
#include <memory>
#include <utility>

#include "ink_chunks.hpp"
#include "penshape/core/base.hpp"

namespace penshape {

using ink_detail::ChunkPieces;
using ink_detail::kChunkSegments;

InkBuilder::InkBuilder(const InkOptions& options)
    : options_(options),
      reach_(std::make_unique<ink_detail::Reach>()),
      fed_(std::make_unique<ink_detail::FedUnion>()) {}
InkBuilder::~InkBuilder() = default;
InkBuilder::InkBuilder(InkBuilder&&) noexcept = default;
InkBuilder& InkBuilder::operator=(InkBuilder&&) noexcept = default;

void InkBuilder::add(const std::vector<InkSample>& samples) {
  samples_.insert(samples_.end(), samples.begin(), samples.end());
}

namespace {

// The plan for `samples`, as ink_polygon() would take it (throws its errors).
ink_detail::Plan plan_of(const std::vector<InkSample>& samples, const InkOptions& options) {
  const double max_error = ink_detail::checked_max_error(options, samples.size());
  return ink_detail::plan_for(max_error, ink_detail::checked_reach(samples));
}

ChunkPieces chunk_of(const std::vector<InkSample>& samples, std::size_t c,
                     const ink_detail::Plan& plan) {
  const std::size_t first = c * kChunkSegments;
  const std::size_t count = std::min(kChunkSegments + 1, samples.size() - first);
  return ink_detail::build_chunk(samples.data() + first, count, plan);
}

} // namespace

std::size_t InkBuilder::built_chunks() const { return chunks_.size(); }

bool InkBuilder::build_next() {
  const std::size_t c = chunks_.size();
  // Chunk c ends at sample (c + 1)·kChunkSegments: complete once that sample arrived (ending the
  // stroke there makes it the last chunk, with the same samples).
  if (invalid_ || !reach_ || samples_.size() < (c + 1) * kChunkSegments + 1) return false;
  try {
    // The plan reads the reach of all samples so far: each new sample is checked once.
    const double max_error = ink_detail::checked_max_error(options_, samples_.size());
    ink_detail::widen_checked_reach(samples_, reached_, *reach_);
    reached_ = samples_.size();
    chunks_.push_back(chunk_of(samples_, c, ink_detail::plan_for(max_error, *reach_)));
  } catch (const InvalidInput&) {
    invalid_ = true; // polygon() throws it again, as ink_polygon() would
    return false;
  }
  // Q's final union takes the chunk's pieces now rather than at pen-up (ink_union.hpp FedUnion).
  if (fed_ && fed_chunks_ == c) {
    fed_->add(chunks_.back().paths);
    ++fed_chunks_;
  }
  return true;
}

InkPolygon InkBuilder::polygon(const std::vector<InkSample>& samples) {
  const ink_detail::Plan plan = plan_of(samples, options_);
  // The built chunks count while the samples they read are the same (bit for bit) and the plan
  // gives the same pieces.
  std::size_t reusable = 0;
  const std::size_t whole = ink_detail::chunk_count(samples.size());
  for (; reusable < chunks_.size() && reusable < whole; ++reusable) {
    const std::size_t last = (reusable + 1) * kChunkSegments; // the chunk's last sample
    const auto read = [](const InkSample& a, const InkSample& b) {
      return a.x == b.x && a.y == b.y && a.radius == b.radius;
    };
    if (last >= samples_.size() || last >= samples.size() ||
        !std::equal(samples_.begin() + static_cast<std::ptrdiff_t>(reusable * kChunkSegments),
                    samples_.begin() + static_cast<std::ptrdiff_t>(last + 1),
                    samples.begin() + static_cast<std::ptrdiff_t>(reusable * kChunkSegments),
                    read) ||
        !ink_detail::same_pieces(chunks_[reusable], plan)) {
      break;
    }
  }
  std::vector<ChunkPieces> rest;
  rest.reserve(whole - reusable);
  for (std::size_t c = reusable; c < whole; ++c) rest.push_back(chunk_of(samples, c, plan));
  std::vector<const ChunkPieces*> all;
  all.reserve(whole);
  for (std::size_t c = 0; c < reusable; ++c) all.push_back(&chunks_[c]);
  for (const ChunkPieces& chunk : rest) all.push_back(&chunk);
  // The union fed while the pen was down holds the first fed_chunks_ chunks in order: usable when
  // all of them are reused, and then spent (one execute); else kept for a later call (a hold's
  // stroke drawn before the pen came to rest, then the whole stroke).
  if (fed_ && fed_chunks_ <= reusable) {
    const std::unique_ptr<ink_detail::FedUnion> fed = std::move(fed_);
    return ink_detail::assemble(all, plan, *fed, std::exchange(fed_chunks_, 0));
  }
  return ink_detail::assemble(all, plan);
}

} // namespace penshape
