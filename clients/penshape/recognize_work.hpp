#pragma once
// `penshape recognize`: the recognition of one file's strokes (each stroke's ink when asked,
// grouping in drawing order, arrows and tidy-up) into answers, one per shape or freeform group.
// Writing strokes (the file is the page) are freeform answers of their own unless --snap-writing.
#include <vector>

#include "penshape/core/group_recognize.hpp"
#include "penshape/core/intent.hpp"
#include "recognize_options.hpp"
#include "stroke_files.hpp"

namespace penshape::cli {

struct RecognizeRow {
  std::vector<const FileStroke*> strokes; // the strokes it covers, in drawing order
  GroupedShape shape;                     // shape.strokes index the batch
  double seconds = 0.0;                   // recognition time spent on its strokes
  IntentDecision intent;                  // writing or drawing (recognize_intent.hpp)
};

// One file's strokes (in drawing order) to answers ordered by their first stroke. Throws
// StrokeFileError ("file:line: problem") for a stroke the recognizer refuses.
std::vector<RecognizeRow> recognize_batch(const std::vector<FileStroke>& batch,
                                          const RecognizeOptions& options);

} // namespace penshape::cli
