#pragma once
#include <span>
#include <string_view>

namespace penshape::cli {
int run_hid_describe(std::span<const std::string_view> args);
int run_hid_tablets(std::span<const std::string_view> args); // hid_tablets_command.cpp
} // namespace penshape::cli
