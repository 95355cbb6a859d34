// `penshape hid describe FILE [--json]`: the report layouts of a HID report descriptor and, for
// a pen, the decoder's fields, maxima and resolution.
#include "hid_describe_command.hpp"

#include <cstdio>
#include <optional>
#include <string>

#include "args.hpp"
#include "command.hpp"
#include "device_args.hpp"
#include "json_writer.hpp"
#include "penshape/drivers/device_profile.hpp"

namespace penshape::cli {
namespace {

using drivers::PenField;
using drivers::PenLayout;
using drivers::ReportLayout;
using drivers::ReportType;

constexpr const char* kHelp =
    "usage: penshape hid describe FILE [--json] [--vid HEX --pid HEX]\n\n"
    "FILE is raw report descriptor bytes (a copy of sysfs report_descriptor), a hid-recorder\n"
    "file (its R: line; its I: line picks the vendor protocol), or a usbhid-dump DESCRIPTOR\n"
    "dump. Prints every input report's fields and, for a pen, the decoded fields, maxima and\n"
    "resolution (units per millimetre), the report family, and the physical size with where it\n"
    "came from: the tablet table, the descriptor's units, or a vendor probe; or a warning that\n"
    "it is unknown (coordinates are then device units, never millimetres).\n\n"
    "--json: {\"reports\": [{\"id\", \"fields\": [{\"usage\", \"bit_offset\", \"size\",\n"
    "\"logical_min\", \"logical_max\"}]}], \"pen\": {\"report_id\", \"x_max\", \"y_max\",\n"
    "\"pressure_max\", \"resolution\", \"family\", \"physical_size_known\", \"width_mm\",\n"
    "\"height_mm\", \"size_source\" (table, descriptor, probe or unknown)} or null}. Bit\n"
    "offsets count from the first byte of the report as hidraw delivers it (the report ID byte\n"
    "included). Exit 2 on a malformed file, naming the byte offset.";

void print_pen_field(const char* name, const PenField& f) {
  if (!f.present()) return;
  std::printf("    %-9s bit %4u size %2u", name, f.bit_offset, f.bit_size);
  if (f.high_bit_size > 0) {
    std::printf(" + bit %u size %u%s", f.high_bit_offset, f.high_bit_size,
                f.high_big_endian ? " (big-endian)" : "");
  }
  if (f.top_bit_size > 0) std::printf(" + bit %u size %u", f.top_bit_offset, f.top_bit_size);
  if (f.total_bits() > 1) {
    std::printf("  logical %d..%d", f.logical_minimum, f.logical_maximum);
  }
  if (f.inverted) std::printf("  (inverted)");
  std::printf("\n");
}

std::string field_usage(const drivers::ReportField& f) {
  if (f.is_constant()) return "padding";
  if (f.is_variable()) return drivers::usage_name(f.usage);
  return drivers::usage_name(f.usage_minimum) + ".." + drivers::usage_name(f.usage_maximum);
}

// The device's profile from the file (and --vid/--pid), or nothing (the error printed).
std::optional<drivers::DeviceProfile> load_profile(const ParsedArgs& parsed) {
  try {
    const drivers::Recording rec = load_device_file(parsed);
    if (rec.descriptor.empty()) throw drivers::RecordingError(0, "the file holds no descriptor");
    return drivers::build_profile(rec.identity, rec.descriptor, rec.vendor_strings);
  } catch (const drivers::RecordingError& e) {
    std::fprintf(stderr, "penshape hid describe: %s: %s\n", device_file_name(parsed).c_str(),
                 e.what());
  } catch (const drivers::DescriptorError& e) {
    std::fprintf(stderr, "penshape hid describe: %s: %s\n", device_file_name(parsed).c_str(),
                 e.what());
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "penshape hid describe: %s: %s\n", device_file_name(parsed).c_str(),
                 e.what());
  }
  return std::nullopt;
}

void json_pen(const drivers::DeviceProfile& profile, JsonWriter& json) {
  const auto& pens = profile.decoder.layouts();
  if (pens.empty()) {
    json.null();
    return;
  }
  json.begin_object();
  json.key("report_id").integer(pens.front().report_id);
  json.key("x_max").integer(profile.info.x_max);
  json.key("y_max").integer(profile.info.y_max);
  json.key("pressure_max").integer(profile.info.pressure_max);
  json.key("resolution").number(profile.info.x_resolution);
  json.key("family").string(profile.family);
  json.key("physical_size_known").boolean(profile.size_source != drivers::SizeSource::kUnknown);
  json.key("width_mm").number(profile.info.width_mm());
  json.key("height_mm").number(profile.info.height_mm());
  json.key("size_source").string(drivers::size_source_name(profile.size_source));
  json.end_object();
}

void print_json(const drivers::DeviceProfile& profile) {
  JsonWriter json;
  json.begin_object().key("reports").begin_array();
  for (const ReportLayout& r : profile.descriptor->reports) {
    if (r.type != ReportType::kInput) continue;
    json.begin_object().key("id").integer(r.report_id).key("fields").begin_array();
    for (const auto& f : r.fields) {
      json.begin_object();
      json.key("usage").string(field_usage(f));
      json.key("bit_offset").integer(f.bit_offset);
      json.key("size").integer(static_cast<std::int64_t>(f.bit_size) * f.count);
      json.key("logical_min").integer(f.logical_minimum);
      json.key("logical_max").integer(f.logical_maximum);
      json.end_object();
    }
    json.end_array().end_object();
  }
  json.end_array().key("pen");
  json_pen(profile, json);
  json.end_object();
  std::puts(json.str().c_str());
}

void print_reports(const drivers::DeviceProfile& profile) {
  const char* kTypes[] = {"input", "output", "feature"};
  for (const ReportLayout& r : profile.descriptor->reports) {
    std::printf("%s report %u: %u bytes\n", kTypes[static_cast<int>(r.type)], r.report_id,
                r.size_bytes());
    for (const auto& f : r.fields) {
      std::printf("  bit %4u size %2u x%-3u %-40s logical %d..%d\n", f.bit_offset, f.bit_size,
                  f.count, field_usage(f).c_str(), f.logical_minimum, f.logical_maximum);
    }
  }
}

void print_pens(const drivers::DeviceProfile& profile) {
  std::printf(
      "pen (%s protocol): x_max %d, y_max %d, pressure_max %u, resolution %.3f x %.3f "
      "units/mm%s\n",
      std::string(drivers::protocol_name(profile.protocol)).c_str(), profile.info.x_max,
      profile.info.y_max, profile.info.pressure_max, profile.info.x_resolution,
      profile.info.y_resolution, profile.info.has_tilt ? ", tilt" : "");
  if (profile.size_source == drivers::SizeSource::kUnknown) {
    std::printf("family %s; physical size unknown: coordinates are device units, not mm\n",
                profile.family.c_str());
  } else {
    std::printf("family %s; size %.1f x %.1f mm from the %s\n", profile.family.c_str(),
                profile.info.width_mm(), profile.info.height_mm(),
                std::string(drivers::size_source_name(profile.size_source)).c_str());
  }
  for (const PenLayout& l : profile.decoder.layouts()) {
    std::printf("  report %u (%s, at least %u bytes)\n", l.report_id, l.origin.c_str(),
                l.min_report_bytes);
    for (const auto& [name, field] : drivers::kNamedPenFields) print_pen_field(name, l.*field);
  }
  for (const auto& n : profile.notes) std::printf("  note: %s\n", n.c_str());
}

} // namespace

int run_hid_describe(std::span<const std::string_view> args) {
  const ParsedArgs parsed(
      args, {.flags = {"--json", "--help"}, .options = {"--vid", "--pid", "--descriptor"}});
  if (parsed.flag("--help")) {
    std::puts(kHelp);
    return kExitOk;
  }
  const std::optional<drivers::DeviceProfile> profile = load_profile(parsed);
  if (!profile) return kExitBadInput;
  if (parsed.flag("--json")) {
    print_json(*profile);
    return kExitOk;
  }
  print_reports(*profile);
  if (profile->decoder.layouts().empty()) {
    std::puts("no pen report");
  } else {
    print_pens(*profile);
  }
  return kExitOk;
}

} // namespace penshape::cli
