#pragma once
// Accuracy of single-stroke recognition on labelled real drawings (recognize_bench): shapes
// named right and non-shapes snapped, on all writers and leave-one-subject-out, the size x pen
// table, and the derivation of the default tolerance's size fractions (recognize.hpp).
#include <set>
#include <string>
#include <vector>

#include "stroke_corpora.hpp"

namespace penshape::bench {

struct AccuracyOptions {
  bool derive_only = false; // print the tolerance derivation, skip the tables
};

// The classes a drawing labelled `label` may be named (null: not a shape class here).
const std::set<std::string>* shape_targets(const std::string& label);
// Whether drawings labelled `label` are non-shapes (must stay freeform).
bool is_non_shape(const std::string& label);

// A drawing of one stroke labelled a shape (the classes it may be named) or a non-shape.
struct Sample {
  const Drawing* drawing = nullptr;
  const std::set<std::string>* targets = nullptr; // null: a non-shape
};
// The single-stroke drawings labelled a shape or a non-shape, in order.
std::vector<Sample> single_stroke_samples(const std::vector<Drawing>& drawings);

// Prints the tables for the drawings (all corpora together and each corpus alone).
void print_accuracy(const std::vector<Drawing>& drawings, const AccuracyOptions& options);

} // namespace penshape::bench
