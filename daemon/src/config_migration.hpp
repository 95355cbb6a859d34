#pragma once
// Reads the config text as TOML (toml++). Files in penshaped's former format (unquoted strings,
// `[device vvvv:pppp]` headers) are not TOML; their error says, line by line, what to write
// instead, e.g. `penshaped.conf:1: listen: write the value in quotes: listen = "unix:/run/p.sock"`.
#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace penshape::daemon::config_detail {

// The parsed document; throws ConfigError naming the file, the line and the key (when the line
// has one) for a syntax error, with the migration hints of every former-format line.
toml::table parse_toml(std::string_view text, const std::string& origin);

} // namespace penshape::daemon::config_detail
