// Stroke and shape ids behind a grouping session's indices (group_history.hpp).
#include "group_history.hpp"

#include <atomic>

#include "penshape/daemon/grouping_settings.hpp"

namespace penshape::daemon {

bool GroupHistory::ensure(StrokeAnalyzer& analyzer, const PenSettings& settings,
                          const GroupingConfig& grouping) {
  if (session_ && settings_ == settings && same_grouping(grouping_, grouping)) return true;
  static std::atomic<std::uint64_t> epochs{0};
  *this = GroupHistory{};
  epoch_ = ++epochs;
  session_ = analyzer.group_session(settings, grouping);
  settings_ = settings;
  grouping_ = grouping;
  return session_ != nullptr;
}

GroupedStrokeAnalysis GroupHistory::add(const Stroke& stroke, bool with_ink,
                                        const CancelHook& cancel, const InkOffload& offload) {
  return session_->add(stroke, with_ink, cancel, offload);
}

GroupedStrokeAnalysis GroupHistory::add_held(const Stroke& partial, const CancelHook& cancel,
                                             const InkOffload& offload) {
  return session_->add_held(partial, cancel, offload);
}

GroupAnswer GroupHistory::take(const GroupedStrokeAnalysis& r, std::uint64_t stroke_id) {
  GroupAnswer out;
  if (r.grouped) stroke_ids_[session_->stroke_count() - 1] = stroke_id;
  const v1::ShapeKind kind = r.analysis.shape.kind();
  const bool snapped = kind != v1::SHAPE_KIND_NONE && kind != v1::SHAPE_KIND_UNSPECIFIED;
  if (snapped && !r.grouped) out.replaced_stroke_ids.push_back(stroke_id);
  if (snapped && r.grouped) {
    for (const std::size_t i : r.strokes) out.replaced_stroke_ids.push_back(this->stroke_id(i, 0));
  }
  for (const std::size_t id : r.superseded) {
    const auto it = answers_.find(id);
    out.supersedes_shape_ids.push_back(it == answers_.end() ? 0 : it->second.shape_id);
    out.supersedes_sequences.push_back(it == answers_.end() ? 0 : it->second.sequence);
    if (it != answers_.end()) answers_.erase(it);
  }
  return out;
}

void GroupHistory::remember(const GroupedStrokeAnalysis& r, std::uint64_t shape_id,
                            std::uint64_t sequence) {
  if (r.grouped) answers_[r.answer] = {shape_id, sequence};
  while (answers_.size() > kRecentAnswers) answers_.erase(answers_.begin());
  if (!session_) return;
  const std::size_t oldest = session_->oldest_retained_stroke();
  while (!stroke_ids_.empty() && stroke_ids_.begin()->first < oldest) {
    stroke_ids_.erase(stroke_ids_.begin());
  }
}

void GroupHistory::rename(std::size_t answer, std::uint64_t shape_id, std::uint64_t sequence) {
  const auto it = answers_.find(answer);
  if (it != answers_.end()) it->second = {shape_id, sequence};
}

GroupHistory GroupHistory::copy() const {
  GroupHistory out;
  out.session_ = session_ ? session_->clone() : nullptr;
  out.settings_ = settings_;
  out.grouping_ = grouping_;
  out.epoch_ = epoch_;
  out.stroke_ids_ = stroke_ids_;
  out.answers_ = answers_;
  return out;
}

std::uint64_t GroupHistory::stroke_id(std::size_t index, std::uint64_t otherwise) const {
  const auto it = stroke_ids_.find(index);
  return it == stroke_ids_.end() ? otherwise : it->second;
}

std::uint64_t GroupHistory::shape_id(std::size_t answer) const {
  const auto it = answers_.find(answer);
  return it == answers_.end() ? 0 : it->second.shape_id;
}

std::shared_ptr<GroupKeys::Group> GroupKeys::get(const std::string& key) {
  std::lock_guard lock(mutex_);
  const auto it = by_key_.find(key);
  if (it != by_key_.end()) {
    recent_.splice(recent_.begin(), recent_, it->second);
    return it->second->second;
  }
  while (!recent_.empty() && recent_.size() >= max_keys_) {
    by_key_.erase(recent_.back().first); // a call still using it keeps its copy alive
    recent_.pop_back();
  }
  recent_.emplace_front(key, std::make_shared<Group>());
  by_key_[key] = recent_.begin();
  return recent_.front().second;
}

std::size_t GroupKeys::size() const {
  std::lock_guard lock(mutex_);
  return recent_.size();
}

} // namespace penshape::daemon
