#include "board_model.hpp"

#include <algorithm>

namespace penshape::board {

void BoardModel::begin_stroke(PointPx p, float pen_radius_px) {
  strokes_.push_back({});
  strokes_.back().points.push_back(p);
  strokes_.back().pen_radius_px = pen_radius_px;
  awaiting_id_.push_back(strokes_.size() - 1);
  drawing_ = true;
}

void BoardModel::extend_stroke(PointPx p) {
  if (drawing_) strokes_.back().points.push_back(p);
}

void BoardModel::end_stroke(PointPx p) {
  extend_stroke(p);
  drawing_ = false;
}

void BoardModel::server_stroke_started(std::uint64_t server_id) {
  if (awaiting_id_.empty()) return;
  const std::size_t index = awaiting_id_.front();
  awaiting_id_.erase(awaiting_id_.begin());
  if (index < strokes_.size()) strokes_[index].server_id = server_id;
}

BoardStroke* BoardModel::find(std::uint64_t server_id) {
  for (auto& s : strokes_) {
    if (s.server_id == server_id && server_id != 0) return &s;
  }
  return nullptr;
}

int BoardModel::server_shape(std::uint64_t server_id, const v1::Shape& shape) {
  BoardStroke* s = find(server_id);
  if (s == nullptr) return -1;
  s->answered = true;
  s->held.reset();
  if (shape.kind() == v1::SHAPE_KIND_NONE || shape.kind() == v1::SHAPE_KIND_UNSPECIFIED) {
    // Writing stays as drawn (the daemon leaves it alone unless snap_writing).
    s->note = shape.intent() == v1::INTENT_WRITING ? "writing" : "no shape";
  } else {
    s->shape = shape;
    s->snapped = true;
  }
  return static_cast<int>(s - strokes_.data());
}

int BoardModel::server_held(std::uint64_t server_id, const v1::Shape& shape) {
  BoardStroke* s = find(server_id);
  if (s == nullptr || s->answered) return -1; // the pen-up answer rules
  s->held = shape;
  s->preview.reset();
  return static_cast<int>(s - strokes_.data());
}

int BoardModel::server_preview(std::uint64_t server_id, const v1::Shape* best) {
  BoardStroke* s = find(server_id);
  if (s == nullptr || s->finished || s->answered) return -1; // too late: the answer rules
  if (best != nullptr) {
    s->preview = *best;
  } else {
    s->preview.reset();
  }
  return static_cast<int>(s - strokes_.data());
}

int BoardModel::server_not_analysed(std::uint64_t server_id, const std::string& why) {
  BoardStroke* s = find(server_id);
  if (s == nullptr) return -1;
  s->answered = true;
  s->note = "not analysed: " + why;
  return static_cast<int>(s - strokes_.data());
}

int BoardModel::server_finished(std::uint64_t server_id) {
  BoardStroke* s = find(server_id);
  if (s == nullptr) return -1;
  s->finished = true;
  s->preview.reset();
  return static_cast<int>(s - strokes_.data());
}

int BoardModel::settle_finished() {
  int settled = 0;
  for (auto& s : strokes_) {
    if (s.finished && !s.answered) {
      s.answered = true;
      s.note = "the daemon sent no shape (no recognizer)";
      ++settled;
    }
  }
  return settled;
}

std::string BoardModel::undo() {
  if (strokes_.empty() || drawing_) return "nothing";
  if (strokes_.back().snapped) {
    strokes_.back().snapped = false;
    return "unsnapped";
  }
  // A stroke the daemon has not answered yet stays: its events are still on their way.
  if (!strokes_.back().answered) return "nothing";
  strokes_.pop_back();
  return "removed";
}

void BoardModel::clear() {
  if (drawing_) return;
  strokes_.clear();
  awaiting_id_.clear();
}

bool BoardModel::all_answered() const {
  return std::all_of(strokes_.begin(), strokes_.end(),
                     [](const BoardStroke& s) { return s.answered; });
}

bool BoardModel::all_finished_or_answered() const {
  return std::all_of(strokes_.begin(), strokes_.end(),
                     [](const BoardStroke& s) { return s.finished || s.answered; });
}

} // namespace penshape::board
