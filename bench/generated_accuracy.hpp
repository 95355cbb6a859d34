#pragma once
// The recognizer's figures on a labelled corpus, for recognize_bench: shapes named right and
// non-shapes left as ink, whole corpus and per subject (leave-one-subject-out is moot: no rule
// is fitted here; the per-subject rows show the spread), and per kind.
#include <set>
#include <string>
#include <vector>

#include "penshape/core/recognize.hpp"

namespace penshape::bench {

struct LabelledStroke {
  std::string kind;            // what was drawn ("circle", "pigtail", "word", ...)
  std::string subject;         // who drew it ("s02", ...)
  std::set<std::string> truth; // classes a correct answer may name; {"freeform"}: a non-shape
  std::vector<StrokePoint> points;
};

// The real $1 logs under `root` (sNN/<speed>/<kind>NN.xml), labelled as the recognizer tests
// read them (circle, rectangle, triangle: shapes; pigtail, question_mark, curly braces,
// delete_mark: non-shapes); the other gestures carry no truth. Empty when `root` is absent.
std::vector<LabelledStroke> real_dollar_strokes(const std::string& root);
// The generated corpus (tests/support/gen: 3 subjects x 3 speeds x 5 of every one-stroke kind),
// labelled with the generator's truth.
std::vector<LabelledStroke> generated_strokes();

// Prints the figures on `strokes` under the title `corpus`: each stroke recognized alone as
// `penshape recognize` does (recognize_strokes: a one-stroke arrow is read there, not by
// recognize()).
void print_labelled_accuracy(const std::string& corpus, const std::vector<LabelledStroke>& strokes);

} // namespace penshape::bench
