#include "device_args.hpp"

#include <charconv>

namespace penshape::cli {
namespace {

std::uint16_t hex_id(const ParsedArgs& args, std::string_view name) {
  const auto v = args.value(name);
  std::uint16_t out = 0;
  const std::string s = v->rfind("0x", 0) == 0 ? v->substr(2) : *v;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out, 16);
  if (s.empty() || r.ec != std::errc{} || r.ptr != s.data() + s.size()) {
    throw UsageError(std::string(name) + " needs a hex USB id such as 056a, got '" + *v + "'");
  }
  return out;
}

} // namespace

drivers::Recording load_device_file(const ParsedArgs& args) {
  if (args.positionals().size() != 1) throw UsageError("expected exactly one FILE");
  drivers::Recording rec = drivers::load_recording_file(args.positionals()[0]);
  const bool vid = args.value("--vid").has_value();
  const bool pid = args.value("--pid").has_value();
  if (vid != pid) throw UsageError("--vid and --pid go together");
  if (vid) {
    rec.identity.vendor_id = hex_id(args, "--vid");
    rec.identity.product_id = hex_id(args, "--pid");
    if (rec.identity.bus == Bus::kUnknown) rec.identity.bus = Bus::kUsb;
    rec.has_identity = true;
  }
  if (const auto d = args.value("--descriptor")) {
    // The descriptor from a separate file (raw bytes, hex dump or hid-recorder): usbhid-dump
    // streams usually come without one.
    const drivers::Recording desc = drivers::load_recording_file(*d);
    if (desc.descriptor.empty()) throw drivers::RecordingError(0, *d + " holds no descriptor");
    rec.descriptor = desc.descriptor;
  }
  return rec;
}

std::string device_file_name(const ParsedArgs& args) {
  return args.positionals().empty() ? std::string() : args.positionals().front();
}

} // namespace penshape::cli
