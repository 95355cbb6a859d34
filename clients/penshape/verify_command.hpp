#pragma once
// `penshape verify FILE ANSWER.json [--json]`: re-checks deconstruction answers independently.
#include <span>
#include <string_view>

namespace penshape::cli {

int run_verify(std::span<const std::string_view> args);

} // namespace penshape::cli
