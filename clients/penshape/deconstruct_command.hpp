#pragma once
#include <span>
#include <string_view>

namespace penshape::cli {
int run_deconstruct(std::span<const std::string_view> args);
}
