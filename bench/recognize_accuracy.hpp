#pragma once
// Accuracy of single-stroke recognition on labelled real drawings (recognize_bench): shapes
// named right and non-shapes snapped, on all writers and leave-one-subject-out, the size x pen
// table, and the derivation of the default tolerance's size fractions (recognize.hpp).
#include <vector>

#include "stroke_corpora.hpp"

namespace penshape::bench {

struct AccuracyOptions {
  bool derive_only = false; // print the tolerance derivation, skip the tables
};

// Prints the tables for the drawings (all corpora together and each corpus alone).
void print_accuracy(const std::vector<Drawing>& drawings, const AccuracyOptions& options);

} // namespace penshape::bench
