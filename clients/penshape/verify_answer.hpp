#pragma once
// Reading a `deconstruct --json` answer back into a claim for the verifier: exact values from
// its "exact" object when present, else the printed decimals read exactly.
#include <string>

#include "json_reader.hpp"
#include "penshape/core/verify.hpp"

namespace penshape::cli {

// Throws InputError naming the field when the answer is not a deconstruction answer.
DeconstructionClaim claim_from_json(const JsonValue& answer);

} // namespace penshape::cli
