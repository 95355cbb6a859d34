#pragma once
// Leave-one-subject-out choice of the classifier's plausibility thresholds (recognize_bench
// --rule-folds): each rule's threshold (and RecognizerConfig::straight_fraction, which the rules
// read) is swept over a grid on every labelled single-stroke
// drawing (and the diamonds and squares on a corner made from real rectangles, the polygons of
// 5-8 corners made from real circles); for each writer
// the value is chosen on the other writers only, and that writer is scored with it. The held-out
// figure beside the rule off and the shipped value says whether the rule helps writers it was
// not tuned on.
#include <vector>

#include "stroke_corpora.hpp"

namespace penshape::bench {

void print_rule_folds(const std::vector<Drawing>& drawings);

} // namespace penshape::bench
