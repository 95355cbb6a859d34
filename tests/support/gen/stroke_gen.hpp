#pragma once
// Pen strokes as people draw them, made by the project for tests and benches that must run
// without the real corpora: shapes in one or several strokes, arrows, and non-shapes (scribbles,
// spirals, handwriting, dots). Each drawing carries its truth: the kind drawn and the recognizer
// classes a correct answer may name. The pen's imperfections — wobble growing with size and
// speed, tremor, open or overshot closure, rounded corners, end hooks, speed and pressure
// profiles — follow measurements of real strokes (stroke_measurements.hpp, made by
// measure_strokes.py). Coordinates are in the $1 logs' pixels (y down), times in seconds.
// A seed fixes every drawing, on every platform.
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::gen {

enum class Speed { kSlow, kMedium, kFast };
const char* to_string(Speed s); // "slow", "medium", "fast"

struct GenStroke {
  std::vector<StrokePoint> points; // integer pixels, seconds from the drawing's start
  std::vector<double> pressure;    // one per point, in (0, 1]
};

struct Drawing {
  std::string kind;            // what was drawn: "circle", "arrow2", "word", ...
  std::set<std::string> truth; // recognizer classes a correct answer may name
  bool is_shape = false;       // false for scribbles, spirals, handwriting, dots
  std::vector<GenStroke> strokes;
};

struct DrawOptions {
  Speed speed = Speed::kMedium;
  double scale = 1.0; // times the measured mean size
  bool hooks = true;  // end hooks at the measured rate
};

// The kinds draw() knows, by group.
const std::vector<std::string>& single_stroke_shape_kinds(); // circle ... arc, arrow1
const std::vector<std::string>& multi_stroke_shape_kinds();  // arrow2, arrow3, rectangle2 ...
const std::vector<std::string>& non_shape_kinds();           // scribble, spiral, letter, word, dot

class StrokeGenerator {
 public:
  explicit StrokeGenerator(std::uint64_t seed);
  ~StrokeGenerator();
  StrokeGenerator(const StrokeGenerator&) = delete;
  StrokeGenerator& operator=(const StrokeGenerator&) = delete;

  // One drawing of `kind` (one of the lists above); throws std::invalid_argument otherwise.
  Drawing draw(const std::string& kind, const DrawOptions& options = {});

 private:
  struct Impl;
  Impl* impl_;
};

// A corpus laid out like the $1 logs: for each subject (one seed each) and speed, `per_kind`
// drawings of every single-stroke kind. Multi-stroke kinds are left out (the $1 format holds one
// stroke).
struct CorpusEntry {
  int subject = 0;
  Speed speed = Speed::kMedium;
  int number = 0; // 1-based within its kind
  Drawing drawing;
};
std::vector<CorpusEntry> single_stroke_corpus(std::uint64_t seed, int subjects, int per_kind);

} // namespace penshape::gen
