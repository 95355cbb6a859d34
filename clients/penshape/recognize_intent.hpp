#pragma once
// `penshape recognize`: the writing/drawing decision (core intent.hpp) on one file's strokes,
// the file being the page (its strokes in order, coordinates taken as millimetres).
#include <vector>

#include "penshape/core/intent.hpp"
#include "stroke_files.hpp"

namespace penshape::cli {

std::vector<IntentDecision> intents_of(const std::vector<FileStroke>& batch);

// An answer's intent: writing when every stroke it covers is writing; its score the mean
// P(writing) of those strokes.
IntentDecision intent_of_answer(const std::vector<IntentDecision>& intents,
                                const std::vector<std::size_t>& strokes);

} // namespace penshape::cli
