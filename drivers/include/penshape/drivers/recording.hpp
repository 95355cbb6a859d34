#pragma once
// Recordings of a device's reports:
//  - hid-recorder text format (read and write): `N:` name, `P:` phys, `I: bus vid pid` (hex),
//    `R: len hex…` the report descriptor, `E: sec.usec len hex…` one input report (report ID
//    included when the device uses IDs). penshape adds one comment kind that other tools
//    ignore: `# penshape-string: <index> hex…` for a USB string descriptor a vendor protocol
//    read (UC-Logic parameters), so a vendor-mode recording replays with the right maxima.
//  - usbhid-dump streams (import): `BBB:DDD:III:STREAM <ts>` / `…:DESCRIPTOR <ts>` followed by
//    hex lines, blank line between blocks.
// Limits: files up to kMaxRecordingBytes (256 MiB); a report up to kMaxReportBytes.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "penshape/drivers/byte_offset_error.hpp"
#include "penshape/drivers/device_profile.hpp"

namespace penshape::drivers {

inline constexpr std::size_t kMaxRecordingBytes = std::size_t{256} << 20;

// Malformed input: `offset` is the byte offset in the file where the problem starts.
struct RecordingError : ByteOffsetError {
  RecordingError(std::size_t offset, const std::string& what)
      : ByteOffsetError("byte", offset, what) {}
};

struct HidEvent {
  std::int64_t time_us = 0; // since the start of the recording
  std::vector<std::uint8_t> bytes;
  friend bool operator==(const HidEvent&, const HidEvent&) = default;
};

struct Recording {
  DeviceIdentity identity;   // name from N:, bus/vid/pid from I:
  bool has_identity = false; // an I: line was present
  std::string phys;
  std::vector<std::uint8_t> descriptor;
  VendorStrings vendor_strings;
  std::vector<HidEvent> events;
  friend bool operator==(const Recording& a, const Recording& b) {
    return a.identity.bus == b.identity.bus && a.identity.vendor_id == b.identity.vendor_id &&
           a.identity.product_id == b.identity.product_id && a.identity.name == b.identity.name &&
           a.has_identity == b.has_identity && a.phys == b.phys && a.descriptor == b.descriptor &&
           a.vendor_strings == b.vendor_strings && a.events == b.events;
  }
};

// hid-recorder. Only the first device of a multi-device file (`D: 0`) is read.
Recording read_hid_recorder(std::string_view text);
std::string write_hid_recorder(const Recording& recording);
// One `E:` line, as the live recorder appends it.
std::string hid_recorder_event_line(const HidEvent& event);
// The header (everything before the events), in hid-recorder's own order: `D: 0`, R:, N:, P:,
// I: (only with has_identity), the vendor strings, `D: 0`. Line breaks in the name and the
// physical path become blanks. The one writer of hid-recorder headers: the live recorder, the
// CLI's captures and its re-encoded recordings all use it.
std::string hid_recorder_header(const Recording& recording);
// `text` with its line breaks as blanks: hid-recorder lines (and comments) end at '\n'.
std::string single_line(std::string text);

struct UsbhidDump {
  std::map<int, std::vector<std::uint8_t>> descriptors; // per interface number
  std::map<int, std::vector<HidEvent>> streams;         // per interface, times relative
  std::map<int, std::int64_t> first_timestamp_us;       // absolute unix time of the first
  std::size_t damaged_blocks = 0; // blocks skipped because their header was cut (e.g. NUL runs)
};

// usbhid-dump. Text that is only hex bytes (no header) is one descriptor for interface -1.
UsbhidDump read_usbhid_dump(std::string_view text);

// Whitespace-separated hex bytes, e.g. a descriptor dump. Throws RecordingError with offset.
std::vector<std::uint8_t> parse_hex_bytes(std::string_view text, std::size_t base_offset = 0);

enum class RecordingFormat { kHidRecorder, kUsbhidDump, kRawBytes };
// hid-recorder if any line starts with "R:" / "E:" / "N:" / "I:"; usbhid-dump if a line ends
// in ":STREAM …" / ":DESCRIPTOR …" or the text is hex only; raw bytes otherwise.
RecordingFormat detect_format(std::string_view contents);

// A usbhid-dump interface as a Recording (descriptor from the same dump when present).
Recording recording_from_dump(const UsbhidDump& dump, int interface, const DeviceIdentity& id);

// Loads any supported file as a Recording: hid-recorder text; a usbhid-dump (the interface with
// the most reports, with that interface's descriptor when the dump has one; a dump holding only
// descriptors gives the first that declares a pen, else the first); or raw descriptor bytes (no
// events). Throws RecordingError.
Recording load_recording_file(const std::filesystem::path& path);

// Reads a whole file (binary). Throws RecordingError (offset 0) when unreadable or too large.
std::string read_file(const std::filesystem::path& path);

} // namespace penshape::drivers
