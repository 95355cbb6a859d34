// `penshape hid tablets [--json]`: the built-in tablet table (every row: VID, PID, name, report
// family, physical size, maxima), so a user can see whether and how their tablet is known.
#include <cstdio>
#include <string>

#include "args.hpp"
#include "command.hpp"
#include "hid_describe_command.hpp"
#include "json_writer.hpp"
#include "penshape/drivers/tablet_table.hpp"

namespace penshape::cli {
namespace {

constexpr const char* kHelp =
    "usage: penshape hid tablets [--json] [--vid HEX]\n\n"
    "Lists the tablet table penshape decodes with: one row per device identifier (models that\n"
    "share a VID:PID are told apart by USB strings or report length). width_mm and height_mm\n"
    "are the active area (0: unknown, the device must tell). --vid keeps one vendor's rows.\n\n"
    "--json prints one object per line: {\"vid\", \"pid\" (4 hex digits), \"name\", \"family\",\n"
    "\"width_mm\", \"height_mm\", \"max_x\", \"max_y\", \"max_pressure\"}.";

std::string hex4(std::uint16_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%04x", v);
  return buf;
}

} // namespace

int run_hid_tablets(std::span<const std::string_view> args) {
  const ParsedArgs parsed(args, {.flags = {"--json", "--help"}, .options = {"--vid"}});
  if (parsed.flag("--help")) {
    std::puts(kHelp);
    return kExitOk;
  }
  if (!parsed.positionals().empty()) throw UsageError("hid tablets takes no file");
  std::optional<unsigned long> vid;
  if (const auto v = parsed.value("--vid")) {
    std::size_t used = 0;
    try {
      vid = std::stoul(*v, &used, 16);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != v->size() || *vid > 0xFFFF) {
      throw UsageError("--vid: expected a hexadecimal vendor ID, got '" + *v + "'");
    }
  }
  const bool json = parsed.flag("--json");
  if (!json) {
    std::printf("%-4s %-4s %-22s %8s %8s %7s %7s %6s  %s\n", "vid", "pid", "family", "width_mm",
                "height_mm", "max_x", "max_y", "press", "name");
  }
  for (const auto& t : drivers::builtin_tablets()) {
    if (vid && t.vendor_id != *vid) continue;
    if (json) {
      JsonWriter w;
      w.begin_object().key("vid").string(hex4(t.vendor_id)).key("pid").string(hex4(t.product_id));
      w.key("name").string(t.name).key("family").string(t.family);
      w.key("width_mm").number(t.width_mm).key("height_mm").number(t.height_mm);
      w.key("max_x").integer(t.x_max).key("max_y").integer(t.y_max);
      w.key("max_pressure").integer(t.pressure_max).end_object();
      std::puts(w.str().c_str());
    } else {
      std::printf("%s %s %-22s %8.2f %8.2f %7d %7d %6u  %s\n", hex4(t.vendor_id).c_str(),
                  hex4(t.product_id).c_str(), t.family.c_str(), t.width_mm, t.height_mm, t.x_max,
                  t.y_max, t.pressure_max, t.name.c_str());
    }
  }
  return kExitOk;
}

} // namespace penshape::cli
