#pragma once
// The grouping window and tidy-up switches penshaped uses for live strokes (each tablet's recent
// strokes are grouped: core/include/penshape/core/group_recognize.hpp): their ranges, their
// penshape.v1 form (GroupingSettings) and the thread-safe store the Config service changes.
#include <mutex>
#include <string>

#include "penshape/core/group_recognize.hpp"
#include "penshape/v1/geometry.pb.h"

namespace penshape::daemon {

// Live grouping bounds: a wider window would keep more strokes' samples in memory per tablet.
inline constexpr std::size_t kMaxLiveGroupStrokes = 8;
inline constexpr double kMaxLivePauseSeconds = 60.0;

// `base` with the fields present in `changes` applied. Throws InvalidInput naming the field
// (`field_prefix` + "max_strokes", ...) for max_strokes outside [1, 8] or max_pause_s outside
// [0, 60] seconds (or not finite).
GroupingConfig apply_grouping(GroupingConfig base, const v1::GroupingSettings& changes,
                              const std::string& field_prefix);

// Every field set.
void to_proto(const GroupingConfig& grouping, v1::GroupingSettings* out);

bool same_grouping(const GroupingConfig& a, const GroupingConfig& b);

// Thread-safe: read by the pipeline for every live stroke, written by the Config service.
class GroupingStore {
 public:
  explicit GroupingStore(GroupingConfig initial = {}) : grouping_(initial) {}
  [[nodiscard]] GroupingConfig get() const;
  // Validates and applies (apply_grouping with prefix "grouping."); returns the new values.
  GroupingConfig update(const v1::GroupingSettings& changes);

 private:
  mutable std::mutex mutex_;
  GroupingConfig grouping_;
};

} // namespace penshape::daemon
