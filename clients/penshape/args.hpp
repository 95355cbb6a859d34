#pragma once
// The command-line parser shared by the subcommands, on CLI11: `--name value`, `--name=value`,
// boolean `--flag`, and positionals (all of them after `--`). Unknown options are errors, and so
// is a value given to a flag; an option given twice keeps its last value.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace penshape::cli {

// Thrown for bad usage; the message names the option. Subcommands turn it into exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ArgSpec {
  std::set<std::string, std::less<>> flags;   // options without a value, e.g. "--json"
  std::set<std::string, std::less<>> options; // options with a value, e.g. "--radius"
};

class ParsedArgs {
 public:
  ParsedArgs(std::span<const std::string_view> args, const ArgSpec& spec);

  [[nodiscard]] bool flag(std::string_view name) const;
  [[nodiscard]] std::optional<std::string> value(std::string_view name) const;
  // The option as a finite double; throws UsageError naming the option when it is not one.
  [[nodiscard]] std::optional<double> number(std::string_view name) const;
  // The option as a whole number in [1, 1e15]; UsageError naming the option otherwise.
  [[nodiscard]] std::optional<std::uint64_t> positive_integer(std::string_view name) const;
  [[nodiscard]] const std::vector<std::string>& positionals() const { return positionals_; }

 private:
  std::set<std::string, std::less<>> flags_;
  std::map<std::string, std::string, std::less<>> values_;
  std::vector<std::string> positionals_;
};

} // namespace penshape::cli
