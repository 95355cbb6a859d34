#pragma once
// Reading a `recognize --json` answer back for the verifier: the class, the shape's parameters
// (printed as shortest round-trip decimals, so read back to the same doubles), epsilon, the pen
// radius and the bound from its certificate, and the stroke lines it covers.
#include <cstddef>
#include <vector>

#include "json_value.hpp"
#include "penshape/core/verify.hpp"

namespace penshape::cli {

struct RecognitionAnswer {
  RecognitionClaim claim;
  std::vector<std::size_t> lines; // the strokes' lines in the stroke file ("lines", else "line")
};

// True for an object `recognize --json` printed as an answer (it has "class").
bool is_recognition_answer(const JsonValue& v);
// True for the summary object `recognize --json --labels` prints last.
bool is_recognition_summary(const JsonValue& v);

// Throws InputError naming the field when something needed is missing or malformed.
RecognitionAnswer recognition_from_json(const JsonValue& answer);

} // namespace penshape::cli
