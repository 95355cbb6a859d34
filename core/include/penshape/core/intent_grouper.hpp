#pragma once
// Grouping that leaves writing alone: a StrokeGrouper that is given each stroke's intent
// (intent.hpp). Drawing strokes are grouped and recognized as before; a writing stroke is a
// freeform answer of its own, is never recognized and never joins a group (unless
// snap_writing, which turns the filter off). A writing dot (a full stop, the dot of an i) is
// writing like any other stroke: freeform, never an error. What
// `penshape recognize` uses; the daemon and `penshape snap` can use it the same way (decide_intent
// on the page or the recent strokes, then add()).
#include <cstddef>
#include <vector>

#include "penshape/core/group_recognize.hpp"
#include "penshape/core/intent.hpp"

namespace penshape {

class IntentGrouper {
 public:
  explicit IntentGrouper(GroupingConfig grouping = {}, RecognizerConfig recognizer = {},
                         bool snap_writing = false);

  // Adds the next stroke in drawing order (its index is the number of strokes added before).
  // Throws InvalidInput as StrokeGrouper::add does, for drawing strokes (and every stroke with
  // snap_writing); a writing stroke is not checked by the recognizer (a dot is fine), but a
  // stroke without samples is refused (InvalidInput) whatever its intent.
  GroupUpdate add(const StrokeInput& stroke, Intent intent);

  // The current answers, ordered by their first stroke; indices are this grouper's. Ids are
  // unique within it (writing answers and grouped answers never share one).
  [[nodiscard]] std::vector<GroupedShape> shapes() const;

  // StrokeGrouper::forget_unreachable (a long live session's memory stays bounded); writing
  // answers, which no later stroke can join, are forgotten too. Indices keep counting.
  void forget_unreachable();

 private:
  StrokeGrouper grouper_;
  bool snap_writing_;
  std::size_t added_ = 0;
  std::vector<std::size_t> grouped_; // this grouper's index of each stroke grouper_ was given
  std::vector<GroupedShape> writing_;
};

} // namespace penshape
