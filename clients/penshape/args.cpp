#include "args.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>

namespace penshape::cli {

namespace {

// The option's name in a CLI11 error ("--radius: 1 required TEXT missing").
std::string option_in(const CLI::Error& e) {
  const std::string what = e.what();
  return what.substr(0, what.find(':'));
}

} // namespace

ParsedArgs::ParsedArgs(std::span<const std::string_view> args, const ArgSpec& spec) {
  CLI::App app;
  app.set_help_flag(); // each subcommand prints its own help text
  app.allow_extras();  // unknown options are named in our own message
  std::map<std::string, CLI::Option*, std::less<>> options;
  for (const std::string& name : spec.flags) {
    options[name] = app.add_flag(name == "--help" ? "-h,--help" : name);
  }
  for (const std::string& name : spec.options) options[name] = app.add_option(name)->take_last();
  app.add_option("positionals", positionals_);
  // After `--` everything is a positional: those are kept apart from CLI11 (whose extras would
  // take them), then appended.
  const auto dash_dash = std::find(args.begin(), args.end(), std::string_view("--"));
  const std::vector<std::string> after(dash_dash == args.end() ? dash_dash : dash_dash + 1,
                                       args.end());
  std::vector<std::string> reversed; // CLI11 takes the arguments last first
  for (auto it = std::make_reverse_iterator(dash_dash); it != args.rend(); ++it) {
    const std::string_view arg = *it;
    // CLI11 would read `--flag=true` as the flag: a flag takes no value at all.
    const std::size_t eq = arg.find('=');
    if (arg.starts_with("--") && eq != std::string_view::npos &&
        spec.flags.contains(arg.substr(0, eq))) {
      throw UsageError("option '" + std::string(arg.substr(0, eq)) + "' takes no value");
    }
    reversed.emplace_back(arg);
  }
  try {
    app.parse(reversed);
  } catch (const CLI::ArgumentMismatch& e) {
    throw UsageError("option '" + option_in(e) + "' needs a value");
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  if (!app.remaining().empty()) {
    const std::string unknown = app.remaining().front(); // remaining() is a copy
    throw UsageError("unknown option '" + unknown.substr(0, unknown.find('=')) + "'");
  }
  positionals_.insert(positionals_.end(), after.begin(), after.end());
  for (const auto& [name, option] : options) {
    if (option->count() == 0) continue;
    if (spec.flags.contains(name)) {
      flags_.insert(name);
    } else {
      values_[name] = option->results().back();
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

std::optional<std::uint64_t> ParsedArgs::positive_integer(std::string_view name) const {
  const auto v = number(name);
  if (!v) return std::nullopt;
  if (*v < 1 || *v > 1e15 || std::floor(*v) != *v) {
    throw UsageError("option '" + std::string(name) + "' needs a positive integer");
  }
  return static_cast<std::uint64_t>(*v);
}

} // namespace penshape::cli
