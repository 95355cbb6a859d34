#include "penshape/drivers/hid_descriptor.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdio>
#include <cstring>
#include <optional>

namespace penshape::drivers {

const ReportLayout* ParsedDescriptor::find(ReportType type, std::uint8_t report_id) const {
  for (const auto& r : reports) {
    if (r.type == type && r.report_id == report_id) return &r;
  }
  return nullptr;
}

namespace {

constexpr std::uint32_t kMaxReportCount = 4096;
constexpr std::uint32_t kMaxValueBits = 32;
constexpr std::size_t kMaxCollectionDepth = 32;
constexpr std::size_t kMaxPushDepth = 16;
constexpr std::size_t kMaxUsages = 4096;

struct LocalState {
  std::vector<Usage> usages;
  std::optional<Usage> usage_minimum;
  std::optional<Usage> usage_maximum;
  void clear() { *this = LocalState{}; }
};

std::int64_t signed_value(std::uint32_t raw, std::size_t size) {
  switch (size) {
    case 1:
      return static_cast<std::int8_t>(raw);
    case 2:
      return static_cast<std::int16_t>(raw);
    case 4:
      return static_cast<std::int32_t>(raw);
    default:
      return 0;
  }
}

// A logical or physical extent as the descriptor's (signed) items declare it.
struct Extent {
  std::int64_t minimum = 0;
  std::int64_t maximum = 0;
  std::uint32_t maximum_raw = 0; // the maximum item's value before sign extension

  void set_maximum(std::uint32_t raw, std::size_t size) {
    maximum = signed_value(raw, size);
    maximum_raw = raw;
  }
  // Devices often write e.g. `Logical Maximum (255)` as the one byte FF (signed -1) after a
  // non-negative minimum; the spec says signed, every host reads it as the intended unsigned
  // value.
  [[nodiscard]] std::int64_t effective_maximum() const {
    if (minimum >= 0 && maximum < minimum) return static_cast<std::int64_t>(maximum_raw);
    return maximum;
  }
};

// Global item state, saved and restored by Push/Pop.
struct GlobalState {
  std::uint16_t usage_page = 0;
  Extent logical;
  Extent physical;
  std::int32_t unit_exponent = 0;
  std::uint32_t unit = 0;
  std::uint32_t report_size = 0;
  std::uint8_t report_id = 0;
  std::uint32_t report_count = 0;
};

std::int32_t clamp32(std::int64_t v) {
  return static_cast<std::int32_t>(std::clamp<std::int64_t>(v, INT32_MIN, INT32_MAX));
}

class Parser {
 public:
  explicit Parser(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  ParsedDescriptor run() {
    if (bytes_.empty()) throw DescriptorError(0, "empty descriptor");
    if (bytes_.size() > kMaxDescriptorBytes) {
      throw DescriptorError(
          kMaxDescriptorBytes,
          "descriptor longer than " + std::to_string(kMaxDescriptorBytes) + " bytes");
    }
    std::size_t pos = 0;
    while (pos < bytes_.size()) {
      offset_ = pos;
      const std::uint8_t prefix = bytes_[pos];
      if (prefix == 0xFE) { // long item: FE, bDataSize, bLongItemTag, data
        if (pos + 3 > bytes_.size()) throw DescriptorError(pos, "truncated long item header");
        const std::size_t size = bytes_[pos + 1];
        if (pos + 3 + size > bytes_.size()) throw DescriptorError(pos, "truncated long item");
        ++out_.long_items;
        pos += 3 + size;
        continue;
      }
      static constexpr std::array<std::size_t, 4> kSizes{0, 1, 2, 4};
      const std::size_t size = kSizes[prefix & 3U];
      if (pos + 1 + size > bytes_.size()) {
        throw DescriptorError(pos, "truncated item (prefix 0x" + hex(prefix) + " needs " +
                                       std::to_string(size) + " data bytes)");
      }
      std::uint32_t raw = 0;
      for (std::size_t i = 0; i < size; ++i) {
        raw |= static_cast<std::uint32_t>(bytes_[pos + 1 + i]) << (8 * i);
      }
      const auto type = static_cast<unsigned>((prefix >> 2) & 3U);
      const auto tag = static_cast<unsigned>(prefix >> 4);
      switch (type) {
        case 0:
          main_item(tag, raw);
          break;
        case 1:
          global_item(tag, raw, size);
          break;
        case 2:
          local_item(tag, raw, size);
          break;
        default:
          throw DescriptorError(pos, "reserved item type 3 (prefix 0x" + hex(prefix) + ")");
      }
      pos += 1 + size;
    }
    if (!collections_.empty()) {
      out_.warnings.push_back("byte " + std::to_string(bytes_.size()) + ": " +
                              std::to_string(collections_.size()) +
                              " collection(s) not closed at the end");
    }
    for (auto& r : out_.reports) {
      if (r.size_bits > kMaxReportBytes * 8) {
        throw DescriptorError(offset_, "report " + std::to_string(r.report_id) + " longer than " +
                                           std::to_string(kMaxReportBytes) + " bytes");
      }
    }
    return std::move(out_);
  }

 private:
  static std::string hex(unsigned v) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%02X", v & 0xFFU);
    return buf;
  }

  [[noreturn]] void fail(const std::string& what) const { throw DescriptorError(offset_, what); }

  Usage full_usage(std::uint32_t raw, std::size_t size) const {
    // A 4-byte usage carries its own page (extended usage); shorter ones take the global page.
    if (size == 4) return raw;
    return make_usage(global_.usage_page, static_cast<std::uint16_t>(raw));
  }

  void global_item(unsigned tag, std::uint32_t raw, std::size_t size) {
    switch (tag) {
      case 0x0:
        global_.usage_page = static_cast<std::uint16_t>(raw);
        break;
      case 0x1: // logical minimum
      case 0x3: // physical minimum
        (tag == 0x1 ? global_.logical : global_.physical).minimum = signed_value(raw, size);
        break;
      case 0x2: // logical maximum
      case 0x4: // physical maximum
        (tag == 0x2 ? global_.logical : global_.physical).set_maximum(raw, size);
        break;
      case 0x5:
        // The spec stores the exponent in the low nibble as a 4-bit two's complement value.
        global_.unit_exponent = raw <= 0xF ? (raw >= 8 ? static_cast<std::int32_t>(raw) - 16
                                                       : static_cast<std::int32_t>(raw))
                                           : static_cast<std::int32_t>(signed_value(raw, size));
        break;
      case 0x6:
        global_.unit = raw;
        break;
      case 0x7:
        if (raw > kMaxValueBits) {
          // Wider fields exist only as opaque vendor blobs; keep the layout, values read as 0.
          if (raw > kMaxReportBytes * 8) fail("report size " + std::to_string(raw) + " bits");
        }
        global_.report_size = raw;
        break;
      case 0x8:
        if (raw == 0 || raw > 255) fail("report ID " + std::to_string(raw) + " (must be 1..255)");
        global_.report_id = static_cast<std::uint8_t>(raw);
        out_.uses_report_ids = true;
        break;
      case 0x9:
        if (raw > kMaxReportCount) fail("report count " + std::to_string(raw) + " over limit");
        global_.report_count = raw;
        break;
      case 0xA:
        if (stack_.size() >= kMaxPushDepth) fail("push nested deeper than 16");
        stack_.push_back(global_);
        break;
      case 0xB:
        if (stack_.empty()) fail("pop without push");
        global_ = stack_.back();
        stack_.pop_back();
        break;
      default:
        fail("reserved global item tag 0x" + hex(tag));
    }
  }

  void local_item(unsigned tag, std::uint32_t raw, std::size_t size) {
    switch (tag) {
      case 0x0:
        if (local_.usages.size() >= kMaxUsages) fail("too many usages");
        local_.usages.push_back(full_usage(raw, size));
        break;
      case 0x1:
        local_.usage_minimum = full_usage(raw, size);
        break;
      case 0x2:
        local_.usage_maximum = full_usage(raw, size);
        break;
      case 0x3:
      case 0x4:
      case 0x5:
      case 0x7:
      case 0x8:
      case 0x9:
      case 0xA:
        break; // designators, strings and delimiters do not change the layout
      default:
        fail("reserved local item tag 0x" + hex(tag));
    }
    if (local_.usage_minimum && local_.usage_maximum && (tag == 1 || tag == 2)) {
      // A complete range expands in place, in the order usages were declared.
      Usage lo = *local_.usage_minimum;
      Usage hi = *local_.usage_maximum;
      if (hi < lo) {
        out_.warnings.push_back("byte " + std::to_string(offset_) +
                                ": usage maximum below usage minimum");
        std::swap(lo, hi);
      }
      range_lo_ = lo;
      range_hi_ = hi;
      if (static_cast<std::uint64_t>(hi) - lo + local_.usages.size() < kMaxUsages) {
        for (Usage u = lo;; ++u) {
          local_.usages.push_back(u);
          if (u == hi) break;
        }
      } else {
        huge_range_ = true; // keyboards declare 0..FFFF arrays; keep only the bounds
      }
      local_.usage_minimum.reset();
      local_.usage_maximum.reset();
    }
  }

  void main_item(unsigned tag, std::uint32_t raw) {
    switch (tag) {
      case 0x8:
        add_fields(ReportType::kInput, raw);
        break;
      case 0x9:
        add_fields(ReportType::kOutput, raw);
        break;
      case 0xB:
        add_fields(ReportType::kFeature, raw);
        break;
      case 0xA: {
        if (collections_.size() >= kMaxCollectionDepth) fail("collections nested deeper than 32");
        const Usage u = local_.usages.empty() ? 0 : local_.usages.front();
        collections_.push_back(u);
        if (collections_.size() == 1 && (raw & 0xFF) == 1) {
          application_ = u;
          out_.applications.push_back(u);
        } else if (collections_.size() == 1) {
          application_ = u; // a top-level non-application collection still groups its reports
        }
        break;
      }
      case 0xC:
        if (collections_.empty()) fail("end collection without collection");
        collections_.pop_back();
        if (collections_.empty()) application_ = 0;
        break;
      default:
        fail("reserved main item tag 0x" + hex(tag));
    }
    local_.clear();
    range_lo_ = range_hi_ = 0;
    huge_range_ = false;
  }

  ReportLayout& report_for(ReportType type) {
    for (auto& r : out_.reports) {
      if (r.type == type && r.report_id == global_.report_id) return r;
    }
    ReportLayout r;
    r.type = type;
    r.report_id = global_.report_id;
    r.size_bits = out_.uses_report_ids ? 8 : 0;
    out_.reports.push_back(std::move(r));
    return out_.reports.back();
  }

  void check_report_ids() const {
    if (global_.report_id == 0 && out_.uses_report_ids) {
      fail("main item without a report ID after report IDs were declared");
    }
    if (out_.uses_report_ids && !out_.reports.empty() &&
        std::any_of(out_.reports.begin(), out_.reports.end(),
                    [](const ReportLayout& r) { return r.report_id == 0 && !r.fields.empty(); })) {
      fail("report IDs declared after fields without one");
    }
  }

  // What every field of this main item shares: the global state and the enclosing collections.
  ReportField base_field(ReportType type, std::uint32_t flags) const {
    ReportField base;
    base.type = type;
    base.report_id = global_.report_id;
    base.bit_size = global_.report_size;
    base.flags = flags;
    base.logical_minimum = clamp32(global_.logical.minimum);
    base.logical_maximum = clamp32(global_.logical.effective_maximum());
    base.physical_minimum = clamp32(global_.physical.minimum);
    base.physical_maximum = clamp32(global_.physical.effective_maximum());
    if (base.physical_minimum == 0 && base.physical_maximum == 0) {
      // HID 1.11 §6.2.2.7: both zero means "same as the logical extents".
      base.physical_minimum = base.logical_minimum;
      base.physical_maximum = base.logical_maximum;
    }
    base.unit = global_.unit;
    base.unit_exponent = global_.unit_exponent;
    base.application = application_;
    base.collection = collections_.empty() ? 0 : collections_.back();
    return base;
  }

  // A variable item: one field per value, each with its own usage.
  void add_variable_fields(ReportLayout& report, const ReportField& base) const {
    for (std::uint32_t i = 0; i < global_.report_count; ++i) {
      ReportField f = base;
      f.bit_offset = report.size_bits + i * global_.report_size;
      f.count = 1;
      if (!local_.usages.empty()) {
        // Fewer usages than values: the last usage repeats (HID 1.11 §6.2.2.8).
        f.usage = local_.usages[std::min<std::size_t>(i, local_.usages.size() - 1)];
      } else if (huge_range_) {
        f.usage = range_lo_ + i <= range_hi_ ? range_lo_ + i : range_hi_;
      }
      report.fields.push_back(f);
    }
  }

  // An array item: one field whose values are usages in a range.
  void add_array_field(ReportLayout& report, ReportField base) const {
    base.bit_offset = report.size_bits;
    base.count = global_.report_count;
    if (huge_range_) {
      base.usage_minimum = range_lo_;
      base.usage_maximum = range_hi_;
    } else if (!local_.usages.empty()) {
      base.usage_minimum = *std::min_element(local_.usages.begin(), local_.usages.end());
      base.usage_maximum = *std::max_element(local_.usages.begin(), local_.usages.end());
    }
    report.fields.push_back(base);
  }

  void add_fields(ReportType type, std::uint32_t flags) {
    check_report_ids();
    ReportLayout& report = report_for(type);
    const std::uint64_t bits =
        static_cast<std::uint64_t>(global_.report_size) * global_.report_count;
    if (report.size_bits + bits > kMaxReportBytes * 8) {
      fail("report " + std::to_string(report.report_id) + " longer than " +
           std::to_string(kMaxReportBytes) + " bytes");
    }
    ReportField base = base_field(type, flags);
    if ((flags & kConstant) != 0 || global_.report_count == 0 || global_.report_size == 0) {
      if (bits > 0) { // padding or a constant: kept whole
        base.bit_offset = report.size_bits;
        base.count = global_.report_count;
        report.fields.push_back(base);
      }
    } else if ((flags & kVariable) != 0) {
      add_variable_fields(report, base);
    } else {
      add_array_field(report, base);
    }
    report.size_bits += static_cast<std::uint32_t>(bits);
  }

  std::span<const std::uint8_t> bytes_;
  std::size_t offset_ = 0;
  ParsedDescriptor out_;
  GlobalState global_;
  std::vector<GlobalState> stack_;
  LocalState local_;
  Usage range_lo_ = 0;
  Usage range_hi_ = 0;
  bool huge_range_ = false;
  std::vector<Usage> collections_;
  Usage application_ = 0;
};

} // namespace

ParsedDescriptor parse_report_descriptor(std::span<const std::uint8_t> bytes) {
  return Parser(bytes).run();
}

std::uint32_t extract_bits(std::span<const std::uint8_t> report, std::uint32_t bit_offset,
                           std::uint32_t bit_size) {
  std::uint64_t value = 0;
  const std::size_t first = bit_offset / 8;
  const std::size_t last = (static_cast<std::size_t>(bit_offset) + bit_size + 7) / 8;
  if constexpr (std::endian::native == std::endian::little) {
    // Fast path (the decoder's hot loop): one unaligned 8-byte load when the report has them.
    if (first + 8 <= report.size()) {
      std::memcpy(&value, report.data() + first, 8);
      value >>= bit_offset % 8;
      if (bit_size >= 32) return static_cast<std::uint32_t>(value);
      return static_cast<std::uint32_t>(value & ((std::uint64_t{1} << bit_size) - 1));
    }
  }
  for (std::size_t i = first; i < last && i < report.size() && i - first < 8; ++i) {
    value |= static_cast<std::uint64_t>(report[i]) << (8 * (i - first));
  }
  value >>= bit_offset % 8;
  if (bit_size >= 32) return static_cast<std::uint32_t>(value);
  return static_cast<std::uint32_t>(value & ((std::uint64_t{1} << bit_size) - 1));
}

std::int32_t sign_extend(std::uint32_t value, std::uint32_t bit_size) {
  if (bit_size == 0 || bit_size >= 32) return static_cast<std::int32_t>(value);
  const std::uint32_t sign = 1U << (bit_size - 1);
  return static_cast<std::int32_t>((value ^ sign)) - static_cast<std::int32_t>(sign);
}

std::string usage_name(Usage usage) {
  const std::uint16_t page = usage_page(usage);
  const std::uint16_t id = usage_id(usage);
  struct Name {
    std::uint16_t page, id;
    const char* name;
  };
  static constexpr std::array kNames{
      Name{0x01, 0x01, "Generic Desktop/Pointer"},
      Name{0x01, 0x02, "Generic Desktop/Mouse"},
      Name{0x01, 0x06, "Generic Desktop/Keyboard"},
      Name{0x01, 0x30, "Generic Desktop/X"},
      Name{0x01, 0x31, "Generic Desktop/Y"},
      Name{0x01, 0x32, "Generic Desktop/Z"},
      Name{0x01, 0x38, "Generic Desktop/Wheel"},
      Name{0x0D, 0x01, "Digitizer/Digitizer"},
      Name{0x0D, 0x02, "Digitizer/Pen"},
      Name{0x0D, 0x04, "Digitizer/Touch Screen"},
      Name{0x0D, 0x05, "Digitizer/Touch Pad"},
      Name{0x0D, 0x20, "Digitizer/Stylus"},
      Name{0x0D, 0x22, "Digitizer/Finger"},
      Name{0x0D, 0x30, "Digitizer/Tip Pressure"},
      Name{0x0D, 0x32, "Digitizer/In Range"},
      Name{0x0D, 0x3C, "Digitizer/Invert"},
      Name{0x0D, 0x3D, "Digitizer/X Tilt"},
      Name{0x0D, 0x3E, "Digitizer/Y Tilt"},
      Name{0x0D, 0x42, "Digitizer/Tip Switch"},
      Name{0x0D, 0x43, "Digitizer/Secondary Tip Switch"},
      Name{0x0D, 0x44, "Digitizer/Barrel Switch"},
      Name{0x0D, 0x45, "Digitizer/Eraser"},
      Name{0x0D, 0x5A, "Digitizer/Secondary Barrel Switch"},
      Name{0x0D, 0x5B, "Digitizer/Transducer Serial Number"},
  };
  for (const auto& n : kNames) {
    if (n.page == page && n.id == id) return n.name;
  }
  char buf[32];
  if (page == 0x09) {
    std::snprintf(buf, sizeof buf, "Button/%u", static_cast<unsigned>(id));
  } else {
    std::snprintf(buf, sizeof buf, "0x%04X/0x%04X", static_cast<unsigned>(page),
                  static_cast<unsigned>(id));
  }
  return buf;
}

} // namespace penshape::drivers
