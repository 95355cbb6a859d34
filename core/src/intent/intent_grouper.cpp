// Grouping that leaves writing alone (intent_grouper.hpp).
#include "penshape/core/intent_grouper.hpp"

#include <algorithm>

#include "penshape/core/deconstruct.hpp"

namespace penshape {
namespace {

// Grouped answers take even ids, writing answers odd ones: unique without a shared counter.
std::size_t grouped_id(std::size_t id) { return 2 * id; }
std::size_t writing_id(std::size_t k) { return 2 * k + 1; }

} // namespace

IntentGrouper::IntentGrouper(GroupingConfig grouping, RecognizerConfig recognizer,
                             bool snap_writing)
    : grouper_(grouping, recognizer), snap_writing_(snap_writing) {}

GroupUpdate IntentGrouper::add(const StrokeInput& stroke, Intent intent) {
  const std::size_t index = added_;
  // A stroke without samples is bad input whatever its intent (a dot has one).
  if (stroke.samples.empty()) throw InvalidInput("recognize: the stroke has no samples");
  if (intent == Intent::kWriting && !snap_writing_) {
    GroupedShape answer;
    answer.id = writing_id(writing_.size());
    answer.strokes = {index};
    writing_.push_back(answer);
    ++added_;
    return {answer, {}, {}};
  }
  GroupUpdate update = grouper_.add(stroke);
  grouped_.push_back(index);
  ++added_;
  update.shape.id = grouped_id(update.shape.id);
  for (std::size_t& s : update.shape.strokes) s = grouped_[s];
  for (std::size_t& id : update.superseded) id = grouped_id(id);
  for (std::size_t& s : update.replaced_strokes) s = grouped_[s];
  return update;
}

void IntentGrouper::forget_unreachable() {
  grouper_.forget_unreachable();
  writing_.clear();
}

std::vector<GroupedShape> IntentGrouper::shapes() const {
  std::vector<GroupedShape> out = writing_;
  for (GroupedShape g : grouper_.shapes()) {
    g.id = grouped_id(g.id);
    for (std::size_t& s : g.strokes) s = grouped_[s];
    out.push_back(std::move(g));
  }
  std::sort(out.begin(), out.end(), [](const GroupedShape& a, const GroupedShape& b) {
    return a.strokes.front() < b.strokes.front();
  });
  return out;
}

} // namespace penshape
