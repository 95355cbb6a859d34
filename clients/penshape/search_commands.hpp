#pragma once
// The parameter-search subcommands (one file each).
#include <span>
#include <string_view>

namespace penshape::cli {
int run_search_tolerance(std::span<const std::string_view> args);
int run_search_radius(std::span<const std::string_view> args);
int run_suggest_radius(std::span<const std::string_view> args);
} // namespace penshape::cli
