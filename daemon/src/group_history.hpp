#pragma once
// One grouping of strokes (a tablet's live strokes, a StreamSamples stream, a SubmitStroke
// group_key) with the ids its answers stand for: the analyzer's StrokeGroupSession numbers strokes
// and answers by its own indices; this maps them to stroke ids and published shape ids, so that an
// answer can name the strokes whose ink it replaces and the earlier answers it supersedes.
// Memory follows the grouping window: the session forgets strokes no later stroke can reach, and
// only the ids of strokes it still keeps and of its recent answers are kept here.
#include <cstddef>
#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "penshape/daemon/pen_settings.hpp"
#include "penshape/daemon/stroke_analyzer.hpp"

namespace penshape::daemon {

// What an answer names besides its shape (ShapeRecognized / SubmitStrokeResponse fields).
struct GroupAnswer {
  std::vector<std::uint64_t> replaced_stroke_ids;  // empty when the shape is NONE
  std::vector<std::uint64_t> supersedes_shape_ids; // 0 for an answer no longer known
  std::vector<std::uint64_t> supersedes_sequences; // LiveEvent.sequence, 0 when not known
};

class GroupHistory {
 public:
  // Starts afresh when there is no session yet or the settings or grouping changed (Config);
  // false when the analyzer does not group.
  bool ensure(StrokeAnalyzer& analyzer, const PenSettings& settings,
              const GroupingConfig& grouping);
  // The stroke added to the session (ensure() first). Throws as StrokeGroupSession::add.
  GroupedStrokeAnalysis add(const Stroke& stroke, bool with_ink, const CancelHook& cancel,
                            const InkOffload& offload = {});
  // The stroke so far of a hold added to the session (StrokeGroupSession::add_held).
  GroupedStrokeAnalysis add_held(const Stroke& partial, const CancelHook& cancel,
                                 const InkOffload& offload);
  // After add(), before r's shape is moved out (it reads its kind): the strokes and earlier
  // answers `r` replaces (those answers are then forgotten: never superseded twice).
  GroupAnswer take(const GroupedStrokeAnalysis& r, std::uint64_t stroke_id);
  // After take(): the answer's published id and hub sequence (0 when not published), so a later
  // answer can name it; ids of strokes the session forgot are dropped.
  void remember(const GroupedStrokeAnalysis& r, std::uint64_t shape_id, std::uint64_t sequence);
  // A remembered answer now published under another id (a hold's final shape after a drag).
  void rename(std::size_t answer, std::uint64_t shape_id, std::uint64_t sequence);

  // For previews: a copy whose session is independent, and what its indices stand for.
  [[nodiscard]] GroupHistory copy() const;
  [[nodiscard]] StrokeGroupSession* session() const { return session_.get(); }
  // Which start afresh this history (or the one it was copied from) is on: ensure() changes it
  // whenever it starts afresh, so work prepared on an older history is known to be stale.
  [[nodiscard]] std::uint64_t epoch() const { return epoch_; }
  // The stroke id at a session index, or `otherwise` when not known.
  [[nodiscard]] std::uint64_t stroke_id(std::size_t index, std::uint64_t otherwise) const;
  // The shape id of a session answer, or 0 when not known.
  [[nodiscard]] std::uint64_t shape_id(std::size_t answer) const;
  // Ids kept (tests: they stay within the window).
  [[nodiscard]] std::size_t ids_kept() const { return stroke_ids_.size() + answers_.size(); }

  // Recent answers kept: a group only absorbs answers of its last max_strokes (<= 8) groups, so
  // older ones are never superseded.
  static constexpr std::size_t kRecentAnswers = 64;

 private:
  struct Answer {
    std::uint64_t shape_id = 0;
    std::uint64_t sequence = 0;
  };
  std::unique_ptr<StrokeGroupSession> session_;
  std::uint64_t epoch_ = 0;
  PenSettings settings_;
  GroupingConfig grouping_;
  std::map<std::size_t, std::uint64_t> stroke_ids_; // by session stroke index
  std::map<std::size_t, Answer> answers_;           // by session answer id, the recent ones
};

// Fills an answer's grouping fields (ShapeRecognized, SubmitStrokeResponse: same field names).
template <typename Message>
void set_group_fields(const GroupAnswer& answer, const std::vector<std::string>& tidy,
                      std::uint64_t shape_id, Message* out) {
  out->set_shape_id(shape_id);
  for (const std::uint64_t id : answer.replaced_stroke_ids) out->add_replaced_stroke_ids(id);
  for (const std::uint64_t id : answer.supersedes_shape_ids) out->add_supersedes_shape_ids(id);
  for (const std::string& t : tidy) out->add_tidy(t);
}

// The groupings of SubmitStroke's group_keys: at most `max_keys`; a new key beyond them forgets
// the least recently used one (its strokes then no longer group with later ones). A key's
// grouping is used under its own mutex, so strokes of one key are added one at a time.
class GroupKeys {
 public:
  struct Group {
    std::mutex mutex;
    GroupHistory history; // guarded by mutex
  };
  explicit GroupKeys(std::size_t max_keys) : max_keys_(max_keys) {}
  // The grouping of `key`, created when new; it is now the most recently used.
  std::shared_ptr<Group> get(const std::string& key);
  [[nodiscard]] std::size_t size() const;

 private:
  using Entry = std::pair<std::string, std::shared_ptr<Group>>;
  std::size_t max_keys_;
  mutable std::mutex mutex_;
  std::list<Entry> recent_; // most recently used first
  std::map<std::string, std::list<Entry>::iterator> by_key_;
};

} // namespace penshape::daemon
