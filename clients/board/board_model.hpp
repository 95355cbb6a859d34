#pragma once
// What the drawing board shows: the strokes drawn so far, each raw (the pen's path) or snapped
// (the shape the daemon certified), with undo back to the raw stroke. No SDL, no gRPC here.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "penshape/v1/shape.pb.h"

namespace penshape::board {

struct PointPx {
  float x = 0;
  float y = 0;
};

struct BoardStroke {
  std::vector<PointPx> points;      // window pixels, tip down
  float pen_radius_px = 4;          // the pen radius when it was drawn
  std::uint64_t server_id = 0;      // the daemon's stroke id (0 until StrokeStarted arrives)
  std::optional<v1::Shape> shape;   // a certified shape (never SHAPE_KIND_NONE)
  std::optional<v1::Shape> preview; // while drawing: what it would snap to now (a hint)
  std::optional<v1::Shape> held;    // hold to snap: the certified shape shown while the pen is
                                    // still down (it follows the pen), until pen-up commits
  bool snapped = false;             // shape shown instead of the raw stroke
  bool finished = false;            // StrokeFinished arrived (a shape may follow)
  bool answered = false;            // the daemon has answered (shape, none, or not analysed)
  std::string note;                 // e.g. "not analysed: ..." or "no shape"
};

class BoardModel {
 public:
  void begin_stroke(PointPx p, float pen_radius_px);
  void extend_stroke(PointPx p);
  void end_stroke(PointPx p);
  [[nodiscard]] bool drawing() const { return drawing_; }

  // The daemon's StrokeStarted: its ids arrive in the order the strokes were drawn.
  void server_stroke_started(std::uint64_t server_id);
  // The result for a server stroke; returns the stroke's index, or -1 when unknown.
  int server_shape(std::uint64_t server_id, const v1::Shape& shape);
  int server_not_analysed(std::uint64_t server_id, const std::string& why);
  // Hold to snap: the shape the stroke snapped to while the pen is still down, or its update as
  // it follows the pen (HOLD, FOLLOW); the pen-up answer (server_shape) commits or replaces it.
  int server_held(std::uint64_t server_id, const v1::Shape& shape);
  // A preview of a stroke still being drawn (the best candidate; none clears it).
  int server_preview(std::uint64_t server_id, const v1::Shape* best);
  // StrokeFinished with its analysis done: a ShapeRecognized, when the daemon recognizes shapes,
  // follows right after it on the same stream.
  int server_finished(std::uint64_t server_id);
  // After the stream has been drained (DaemonLink::start ends the previous call only once the
  // daemon has sent everything): finished strokes that got no shape never will (the daemon has
  // no recognizer). Returns how many strokes this settled.
  int settle_finished();

  // Undo acts on the last stroke: a snapped one goes back to its raw form, a raw one is removed.
  // Returns what it did ("unsnapped", "removed", "nothing").
  std::string undo();
  void clear();

  [[nodiscard]] const std::vector<BoardStroke>& strokes() const { return strokes_; }
  [[nodiscard]] bool all_answered() const;
  [[nodiscard]] bool all_finished_or_answered() const;

 private:
  BoardStroke* find(std::uint64_t server_id);
  std::vector<BoardStroke> strokes_;
  std::vector<std::size_t> awaiting_id_; // strokes sent, waiting for their StrokeStarted
  bool drawing_ = false;
};

} // namespace penshape::board
