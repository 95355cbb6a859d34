#include "args.hpp"

#include <charconv>
#include <cmath>

namespace penshape::cli {

ParsedArgs::ParsedArgs(std::span<const std::string_view> args, const ArgSpec& spec) {
  bool only_positionals = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view arg = args[i];
    if (!only_positionals && arg == "-h" && spec.flags.contains("--help")) {
      flags_.insert("--help"); // the short form every subcommand's help answers to
      continue;
    }
    if (only_positionals || arg.size() < 2 || arg.substr(0, 2) != "--") {
      if (!only_positionals && arg.size() > 1 && arg[0] == '-' && arg != "-") {
        throw UsageError("unknown option '" + std::string(arg) + "'");
      }
      positionals_.emplace_back(arg);
      continue;
    }
    if (arg == "--") {
      only_positionals = true;
      continue;
    }
    const auto eq = arg.find('=');
    const std::string name(arg.substr(0, eq));
    if (spec.flags.contains(name)) {
      if (eq != std::string_view::npos) throw UsageError("option '" + name + "' takes no value");
      flags_.insert(name);
    } else if (spec.options.contains(name)) {
      if (eq != std::string_view::npos) {
        values_[name] = std::string(arg.substr(eq + 1));
      } else if (i + 1 < args.size()) {
        values_[name] = std::string(args[++i]);
      } else {
        throw UsageError("option '" + name + "' needs a value");
      }
    } else {
      throw UsageError("unknown option '" + name + "'");
    }
  }
}

bool ParsedArgs::flag(std::string_view name) const { return flags_.contains(name); }

std::optional<std::string> ParsedArgs::value(std::string_view name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

std::optional<double> ParsedArgs::number(std::string_view name) const {
  const auto text = value(name);
  if (!text) return std::nullopt;
  double v = 0.0;
  const char* end = text->data() + text->size();
  const auto [ptr, ec] = std::from_chars(text->data(), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v)) {
    throw UsageError("option '" + std::string(name) + "' needs a finite number, got '" + *text +
                     "'");
  }
  return v;
}

} // namespace penshape::cli
