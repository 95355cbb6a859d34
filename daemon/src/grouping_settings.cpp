// Ranges, proto form and store of the live grouping settings (grouping_settings.hpp).
#include "penshape/daemon/grouping_settings.hpp"

#include <cmath>
#include <sstream>

#include "penshape/core/deconstruct.hpp"

namespace penshape::daemon {

GroupingConfig apply_grouping(GroupingConfig base, const v1::GroupingSettings& changes,
                              const std::string& field_prefix) {
  const v1::GroupingSettings& g = changes;
  if (g.has_disabled()) base.enabled = !g.disabled();
  if (g.has_max_strokes()) {
    if (g.max_strokes() < 1 || g.max_strokes() > kMaxLiveGroupStrokes) {
      throw InvalidInput(field_prefix + "max_strokes is " + std::to_string(g.max_strokes()) +
                         "; expected an integer in [1, 8]");
    }
    base.max_strokes = g.max_strokes();
  }
  if (g.has_max_pause_s()) {
    if (!std::isfinite(g.max_pause_s()) || g.max_pause_s() < 0 ||
        g.max_pause_s() > kMaxLivePauseSeconds) {
      std::ostringstream value;
      value << g.max_pause_s();
      throw InvalidInput(field_prefix + "max_pause_s is " + value.str() +
                         "; expected seconds in [0, 60]");
    }
    base.max_pause_seconds = g.max_pause_s();
  }
  TidyConfig& t = base.tidy;
  if (g.has_tidy_circle()) t.circle = g.tidy_circle();
  if (g.has_tidy_right_angles()) t.right_angles = g.tidy_right_angles();
  if (g.has_tidy_equal_sides()) t.equal_sides = g.tidy_equal_sides();
  if (g.has_tidy_axis()) t.axis = g.tidy_axis();
  if (g.has_tidy_parallel()) t.parallel = g.tidy_parallel();
  if (g.has_tidy_connection()) t.connection = g.tidy_connection();
  return base;
}

void to_proto(const GroupingConfig& grouping, v1::GroupingSettings* out) {
  out->set_disabled(!grouping.enabled);
  out->set_max_strokes(static_cast<std::uint32_t>(grouping.max_strokes));
  out->set_max_pause_s(grouping.max_pause_seconds);
  const TidyConfig& t = grouping.tidy;
  out->set_tidy_circle(t.circle);
  out->set_tidy_right_angles(t.right_angles);
  out->set_tidy_equal_sides(t.equal_sides);
  out->set_tidy_axis(t.axis);
  out->set_tidy_parallel(t.parallel);
  out->set_tidy_connection(t.connection);
}

bool same_grouping(const GroupingConfig& a, const GroupingConfig& b) {
  const TidyConfig& s = a.tidy;
  const TidyConfig& t = b.tidy;
  return a.enabled == b.enabled && a.max_strokes == b.max_strokes &&
         a.max_pause_seconds == b.max_pause_seconds && s.circle == t.circle &&
         s.right_angles == t.right_angles && s.equal_sides == t.equal_sides && s.axis == t.axis &&
         s.parallel == t.parallel && s.connection == t.connection;
}

GroupingConfig GroupingStore::get() const {
  std::lock_guard lock(mutex_);
  return grouping_;
}

GroupingConfig GroupingStore::update(const v1::GroupingSettings& changes) {
  std::lock_guard lock(mutex_);
  grouping_ = apply_grouping(grouping_, changes, "grouping.");
  return grouping_;
}

} // namespace penshape::daemon
