#pragma once
// Reading a `deconstruct --json` answer back into a claim for the verifier: exact values from
// its "exact" object when present, else the printed decimals read exactly.
#include <string>
#include <string_view>

#include "json_value.hpp"
#include "penshape/core/verify.hpp"

namespace penshape::cli {

// The field `key` of an answer object; InputError naming `path` + key when it is missing.
const JsonValue& answer_field(const JsonValue& v, std::string_view key, const std::string& path);

// Throws InputError naming the field when the answer is not a deconstruction answer.
DeconstructionClaim claim_from_json(const JsonValue& answer);

} // namespace penshape::cli
