#pragma once
// HID report descriptor parser: the whole item grammar of HID 1.11 §6.2.2 (short and long items;
// main, global and local items; push/pop; report IDs; usage pages and extended usages; usage
// ranges; logical and physical extents; unit and unit exponent; collections), giving the field
// layout of every input, output and feature report.
//
// Bit offsets count from the first byte of the report *as hidraw delivers it*, i.e. including
// the report ID byte when the descriptor declares report IDs (then the first field of a report
// starts at bit 8).
//
// Limits (exceeding one is a DescriptorError naming the byte offset):
//   descriptor length       <= kMaxDescriptorBytes (4096, the kernel's HID_MAX_DESCRIPTOR_SIZE)
//   report size (one value) <= 32 bits
//   report count            <= 4096 per main item
//   one report              <= kMaxReportBytes (the kernel's HID_MAX_BUFFER_SIZE, 16384 bytes)
//   collection nesting      <= 32, push depth <= 16, usages per main item <= 4096
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "penshape/drivers/byte_offset_error.hpp"

namespace penshape::drivers {

inline constexpr std::size_t kMaxDescriptorBytes = 4096;
inline constexpr std::size_t kMaxReportBytes = 16384;

// A malformed descriptor: `offset` is the byte offset of the offending item's prefix.
struct DescriptorError : ByteOffsetError {
  DescriptorError(std::size_t offset, const std::string& what)
      : ByteOffsetError("report descriptor byte", offset, what) {}
};

enum class ReportType : std::uint8_t { kInput, kOutput, kFeature };

// A 32-bit usage: page in the high 16 bits, usage ID in the low 16 (HID extended usage form).
using Usage = std::uint32_t;
constexpr Usage make_usage(std::uint16_t page, std::uint16_t id) {
  return (static_cast<Usage>(page) << 16) | id;
}
constexpr std::uint16_t usage_page(Usage u) { return static_cast<std::uint16_t>(u >> 16); }
constexpr std::uint16_t usage_id(Usage u) { return static_cast<std::uint16_t>(u & 0xFFFF); }

// Main item data bits (HID 1.11 §6.2.2.5).
enum MainFlags : std::uint32_t {
  kConstant = 1U << 0, // else data
  kVariable = 1U << 1, // else array
  kRelative = 1U << 2, // else absolute
  kWrap = 1U << 3,
  kNonLinear = 1U << 4,
  kNoPreferred = 1U << 5,
  kNullState = 1U << 6,
  kVolatile = 1U << 7,
  kBufferedBytes = 1U << 8,
};

// One field of a report. A variable main item with report count N yields N fields of count 1
// (each with its own usage); an array item yields one field with `count` slots whose values are
// indices into [usage_minimum, usage_maximum]. Constant items (padding) have usage 0.
struct ReportField {
  ReportType type = ReportType::kInput;
  std::uint8_t report_id = 0; // 0 when the descriptor declares no report IDs
  std::uint32_t bit_offset = 0;
  std::uint32_t bit_size = 0;
  std::uint32_t count = 1;
  std::uint32_t flags = 0; // MainFlags
  Usage usage = 0;         // variable fields
  Usage usage_minimum = 0; // array fields
  Usage usage_maximum = 0;
  std::int32_t logical_minimum = 0;
  std::int32_t logical_maximum = 0;
  std::int32_t physical_minimum = 0;
  std::int32_t physical_maximum = 0;
  std::uint32_t unit = 0;
  std::int32_t unit_exponent = 0;
  Usage application = 0; // usage of the enclosing application collection
  Usage collection = 0;  // usage of the innermost enclosing collection

  [[nodiscard]] bool is_constant() const { return (flags & kConstant) != 0; }
  [[nodiscard]] bool is_variable() const { return (flags & kVariable) != 0; }
  [[nodiscard]] bool is_relative() const { return (flags & kRelative) != 0; }
  // Logical values are signed when the logical minimum is negative.
  [[nodiscard]] bool is_signed() const { return logical_minimum < 0; }
};

struct ReportLayout {
  ReportType type = ReportType::kInput;
  std::uint8_t report_id = 0;
  std::uint32_t size_bits = 0; // including the report ID byte when IDs are used
  std::vector<ReportField> fields;
  [[nodiscard]] std::uint32_t size_bytes() const { return (size_bits + 7) / 8; }
};

struct ParsedDescriptor {
  bool uses_report_ids = false;
  std::vector<ReportLayout> reports; // in order of first appearance
  std::vector<Usage> applications;   // top-level application collections, in order
  std::size_t long_items = 0;        // long items seen (HID reserves them; they carry no fields)
  std::vector<std::string> warnings; // tolerated oddities, each naming its byte offset

  [[nodiscard]] const ReportLayout* find(ReportType type, std::uint8_t report_id) const;
};

// Parses a report descriptor. Throws DescriptorError for malformed or over-limit input.
ParsedDescriptor parse_report_descriptor(std::span<const std::uint8_t> bytes);

// Reads an unsigned bit field (little-endian bit order, as HID packs them). Bits beyond the end
// of `report` read as 0. `bit_size` <= 32.
std::uint32_t extract_bits(std::span<const std::uint8_t> report, std::uint32_t bit_offset,
                           std::uint32_t bit_size);

// Sign-extends a `bit_size`-bit value.
std::int32_t sign_extend(std::uint32_t value, std::uint32_t bit_size);

// Short names for the usages tablets use ("Digitizer/Tip Pressure", "Generic Desktop/X"), or
// "0xPPPP/0xUUUU" for others.
std::string usage_name(Usage usage);

} // namespace penshape::drivers
