// `penshape version`: penshape's version and the libraries it was built with.
#include <cstdio>
#include <string>
#include <vector>

#include "args.hpp"
#include "command.hpp"
#include "json_writer.hpp"
#include "penshape/core/version.hpp"
#include "penshape/drivers/hid_enumeration.hpp"
#include "version_command.hpp"

namespace penshape::cli {

int run_version(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args, {.flags = {"--json", "--help"}, .options = {}});
  if (parsed.flag("--help")) {
    std::puts(
        "usage: penshape version [--json]\n\nPrints penshape's version and the versions of "
        "the geometry and device libraries it was built with.");
    return kExitOk;
  }
  std::vector<std::string> components = geometry_library_versions();
  for (auto& v : drivers::device_library_versions()) components.push_back(std::move(v));
  if (parsed.flag("--json")) {
    JsonWriter json;
    json.begin_object();
    json.key("version").string(version());
    json.key("components").begin_array();
    for (const auto& c : components) json.string(c);
    json.end_array();
    json.end_object();
    std::puts(json.str().c_str());
  } else {
    std::printf("penshape %s\n", version().c_str());
    for (const auto& c : components) std::printf("  %s\n", c.c_str());
  }
  return kExitOk;
}

} // namespace penshape::cli
