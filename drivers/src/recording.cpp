#include "penshape/drivers/recording.hpp"

#include "penshape/drivers/pen_layout.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace penshape::drivers {

namespace {

struct Line {
  std::string_view text;
  std::size_t offset; // of the line's first byte in the file
};

std::vector<Line> lines_of(std::string_view text) {
  std::vector<Line> out;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view l = text.substr(start, end - start);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    out.push_back({l, start});
    start = end + 1;
  }
  return out;
}

bool is_space(char c) { return c == ' ' || c == '\t'; }

// Splits on blanks, remembering each token's offset.
std::vector<Line> tokens_of(const Line& line) {
  std::vector<Line> out;
  std::size_t i = 0;
  const auto& t = line.text;
  while (i < t.size()) {
    while (i < t.size() && is_space(t[i])) ++i;
    const std::size_t start = i;
    while (i < t.size() && !is_space(t[i])) ++i;
    if (i > start) out.push_back({t.substr(start, i - start), line.offset + start});
  }
  return out;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::uint8_t hex_byte(const Line& token) {
  if (token.text.size() != 2 || hex_digit(token.text[0]) < 0 || hex_digit(token.text[1]) < 0) {
    throw RecordingError(
        token.offset, "expected a hex byte, found '" + std::string(token.text.substr(0, 16)) + "'");
  }
  return static_cast<std::uint8_t>(hex_digit(token.text[0]) * 16 + hex_digit(token.text[1]));
}

template <typename T>
T parse_number(const Line& token, int base, const char* what) {
  T v{};
  const auto r = std::from_chars(token.text.data(), token.text.data() + token.text.size(), v, base);
  if (r.ec != std::errc{} || r.ptr != token.text.data() + token.text.size()) {
    throw RecordingError(token.offset, std::string("bad ") + what + " '" +
                                           std::string(token.text.substr(0, 16)) + "'");
  }
  return v;
}

// "sec.usec" with up to 6 fraction digits.
std::int64_t parse_timestamp(const Line& token) {
  const auto dot = token.text.find('.');
  const Line sec{token.text.substr(0, dot), token.offset};
  const std::int64_t s = parse_number<std::int64_t>(sec, 10, "timestamp");
  std::int64_t us = 0;
  if (dot != std::string_view::npos) {
    Line frac{token.text.substr(dot + 1), token.offset + dot + 1};
    if (frac.text.empty() || frac.text.size() > 6) {
      throw RecordingError(frac.offset, "timestamp needs 1 to 6 fraction digits");
    }
    us = parse_number<std::int64_t>(frac, 10, "timestamp");
    for (std::size_t i = frac.text.size(); i < 6; ++i) us *= 10;
  }
  if (s < 0 || s > 1'000'000'000'000LL)
    throw RecordingError(token.offset, "timestamp out of range");
  return s * 1'000'000 + us;
}

// "len b0 b1 …" after the line tag, with the count checked.
std::vector<std::uint8_t> counted_bytes(const std::vector<Line>& tokens, std::size_t first,
                                        const Line& line) {
  if (tokens.size() <= first) throw RecordingError(line.offset, "missing byte count");
  const auto n = parse_number<std::size_t>(tokens[first], 10, "byte count");
  if (n > std::max(kMaxReportBytes, kMaxDescriptorBytes)) {
    throw RecordingError(tokens[first].offset, "byte count " + std::to_string(n) + " over limit");
  }
  if (tokens.size() - first - 1 != n) {
    throw RecordingError(line.offset, "line declares " + std::to_string(n) + " bytes but has " +
                                          std::to_string(tokens.size() - first - 1));
  }
  std::vector<std::uint8_t> out;
  out.reserve(n);
  for (std::size_t i = first + 1; i < tokens.size(); ++i) out.push_back(hex_byte(tokens[i]));
  return out;
}

void check_size(std::string_view text) {
  if (text.size() > kMaxRecordingBytes) {
    throw RecordingError(kMaxRecordingBytes, "recording larger than 256 MiB");
  }
}

void append_hex(std::string& out, const std::vector<std::uint8_t>& bytes) {
  char buf[4];
  for (const auto b : bytes) {
    std::snprintf(buf, sizeof buf, " %02x", static_cast<unsigned>(b));
    out += buf;
  }
}

} // namespace

namespace {

// "# penshape-string: N bytes...": a vendor string the device answered (other comments skipped).
void read_comment(const std::vector<Line>& tokens, Recording& rec) {
  if (tokens[0].text != "#" || tokens.size() < 3 || tokens[1].text != "penshape-string:") return;
  const auto index = parse_number<unsigned>(tokens[2], 10, "string index");
  if (index > 255) throw RecordingError(tokens[2].offset, "string index over 255");
  std::vector<std::uint8_t> bytes;
  for (std::size_t i = 3; i < tokens.size(); ++i) bytes.push_back(hex_byte(tokens[i]));
  rec.vendor_strings[static_cast<std::uint8_t>(index)] = std::move(bytes);
}

// The rest of an N: or P: line, without the blanks around it; a lone carriage return inside reads
// as the blank the writer makes of it (round trips).
std::string text_value(const Line& line, const Line& tag) {
  std::string_view rest = line.text.substr(tag.offset - line.offset + 2);
  while (!rest.empty() && (is_space(rest.front()) || rest.front() == '\r')) rest.remove_prefix(1);
  while (!rest.empty() && (is_space(rest.back()) || rest.back() == '\r')) rest.remove_suffix(1);
  return single_line(std::string(rest));
}

void read_identity(const std::vector<Line>& tokens, const Line& line, Recording& rec) {
  if (tokens.size() != 4) throw RecordingError(line.offset, "I: needs bus, vid and pid");
  rec.identity.bus = static_cast<Bus>(parse_number<std::uint16_t>(tokens[1], 16, "bus"));
  rec.identity.vendor_id = parse_number<std::uint16_t>(tokens[2], 16, "vendor id");
  rec.identity.product_id = parse_number<std::uint16_t>(tokens[3], 16, "product id");
  rec.has_identity = true;
}

void read_event(const std::vector<Line>& tokens, const Line& line, Recording& rec) {
  if (tokens.size() < 2) throw RecordingError(line.offset, "E: needs a timestamp");
  HidEvent e;
  e.time_us = parse_timestamp(tokens[1]);
  e.bytes = counted_bytes(tokens, 2, line);
  if (e.bytes.size() > kMaxReportBytes) throw RecordingError(line.offset, "report too long");
  if (!rec.events.empty() && e.time_us < rec.events.back().time_us) {
    throw RecordingError(tokens[1].offset, "timestamps go backwards");
  }
  rec.events.push_back(std::move(e));
}

} // namespace

Recording read_hid_recorder(std::string_view text) {
  check_size(text);
  Recording rec;
  bool have_descriptor = false;
  bool other_device = false; // lines after "D: n", n != 0, belong to another device
  for (const Line& line : lines_of(text)) {
    const auto tokens = tokens_of(line);
    if (tokens.empty()) continue;
    const std::string_view tag = tokens[0].text;
    if (tag.front() == '#') {
      read_comment(tokens, rec);
    } else if (tag == "D:") {
      other_device = tokens.size() >= 2 && tokens[1].text != "0";
    } else if (other_device) {
      continue;
    } else if (tag == "N:" || tag == "P:") {
      (tag == "N:" ? rec.identity.name : rec.phys) = text_value(line, tokens[0]);
    } else if (tag == "I:") {
      read_identity(tokens, line, rec);
    } else if (tag == "R:") {
      if (have_descriptor) throw RecordingError(line.offset, "second R: line for one device");
      rec.descriptor = counted_bytes(tokens, 1, line);
      have_descriptor = true;
    } else if (tag == "E:") {
      read_event(tokens, line, rec);
    } else {
      throw RecordingError(line.offset, "unknown line tag '" + std::string(tag.substr(0, 8)) + "'");
    }
  }
  if (!have_descriptor && rec.events.empty()) {
    throw RecordingError(0, "no R: or E: line: not a hid-recorder file");
  }
  return rec;
}

std::string hid_recorder_event_line(const HidEvent& e) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "E: %lld.%06lld %zu", static_cast<long long>(e.time_us / 1000000),
                static_cast<long long>(e.time_us % 1000000), e.bytes.size());
  std::string out = buf;
  append_hex(out, e.bytes);
  out += '\n';
  return out;
}

std::string single_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

std::string hid_recorder_header(const Recording& r) {
  // hid-recorder's own order, so a file diffs cleanly against one hid-recorder made: D: 0, R:, N:,
  // P:, I:, then (penshape's comments) the vendor strings, and D: 0 before the events.
  std::string out = "D: 0\nR: " + std::to_string(r.descriptor.size());
  append_hex(out, r.descriptor);
  out += "\nN: " + single_line(r.identity.name) + "\nP: " + single_line(r.phys) + "\n";
  if (r.has_identity) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "I: %x %04x %04x\n", static_cast<unsigned>(r.identity.bus),
                  static_cast<unsigned>(r.identity.vendor_id),
                  static_cast<unsigned>(r.identity.product_id));
    out += buf;
  }
  for (const auto& [index, bytes] : r.vendor_strings) {
    out += "# penshape-string: " + std::to_string(index);
    append_hex(out, bytes);
    out += '\n';
  }
  return out + "D: 0\n";
}

std::string write_hid_recorder(const Recording& r) {
  std::string out = hid_recorder_header(r);
  for (const auto& e : r.events) out += hid_recorder_event_line(e);
  return out;
}

std::vector<std::uint8_t> parse_hex_bytes(std::string_view text, std::size_t base_offset) {
  std::vector<std::uint8_t> out;
  for (const Line& line : lines_of(text)) {
    for (Line tok : tokens_of({line.text, line.offset + base_offset})) {
      out.push_back(hex_byte(tok));
    }
  }
  return out;
}

namespace {

// usbhid-dump's blocks: a header "BBB:DDD:III:STREAM|DESCRIPTOR timestamp" then hex lines, a blank
// line between blocks; hex lines without a header form a descriptor of interface -1.
class DumpReader {
 public:
  void line(Line line) {
    // Capture files sometimes start with a run of NUL bytes (a cut-off buffer): skip them.
    std::size_t skip = 0;
    while (skip < line.text.size() && line.text[skip] == '\0') ++skip;
    line.text.remove_prefix(skip);
    line.offset += skip;
    const auto tokens = tokens_of(line);
    if (tokens.empty()) {
      flush();
      return;
    }
    const std::string_view head = tokens[0].text;
    const auto colon = head.rfind(':');
    if (colon != std::string_view::npos &&
        (head.substr(colon + 1) == "STREAM" || head.substr(colon + 1) == "DESCRIPTOR")) {
      header(tokens, line, colon, skip > 0);
      return;
    }
    if (kind_ == Kind::kDamaged) return;
    if (kind_ == Kind::kNone) {
      kind_ = Kind::kHeaderless;
      block_offset_ = line.offset;
      any_ = true;
    }
    for (const Line& tok : tokens) block_.push_back(hex_byte(tok));
  }

  UsbhidDump finish() {
    flush();
    if (!any_) throw RecordingError(0, "no usbhid-dump block");
    return std::move(dump_);
  }

 private:
  enum class Kind : std::uint8_t { kNone, kStream, kDescriptor, kDamaged, kHeaderless };

  void header(const std::vector<Line>& tokens, const Line& line, std::size_t colon, bool damaged) {
    flush();
    any_ = true;
    const std::string_view head = tokens[0].text;
    const auto iface_start = head.rfind(':', colon - 1);
    const bool well_formed = !damaged && iface_start != std::string_view::npos &&
                             std::count(head.begin(), head.end(), ':') == 3 &&
                             hex_digit(head[0]) >= 0;
    if (!well_formed) {
      kind_ = Kind::kDamaged;
      ++dump_.damaged_blocks;
      return;
    }
    iface_ = parse_number<int>(
        {head.substr(iface_start + 1, colon - iface_start - 1), tokens[0].offset + iface_start + 1},
        10, "interface number");
    if (tokens.size() < 2) throw RecordingError(line.offset, "dump header without timestamp");
    ts_ = parse_timestamp(tokens[1]);
    kind_ = head.substr(colon + 1) == "STREAM" ? Kind::kStream : Kind::kDescriptor;
    block_offset_ = line.offset;
  }

  void flush() {
    if (kind_ == Kind::kStream && !block_.empty()) {
      if (block_.size() > kMaxReportBytes) throw RecordingError(block_offset_, "report too long");
      auto& stream = dump_.streams[iface_];
      const auto first = dump_.first_timestamp_us.try_emplace(iface_, ts_).first->second;
      stream.push_back({ts_ - first, block_});
    } else if ((kind_ == Kind::kDescriptor || kind_ == Kind::kHeaderless) && !block_.empty()) {
      dump_.descriptors[kind_ == Kind::kHeaderless ? -1 : iface_] = block_;
    }
    block_.clear();
    kind_ = Kind::kNone;
  }

  UsbhidDump dump_;
  Kind kind_ = Kind::kNone;
  int iface_ = -1;
  std::int64_t ts_ = 0;
  std::vector<std::uint8_t> block_;
  std::size_t block_offset_ = 0;
  bool any_ = false;
};

} // namespace

UsbhidDump read_usbhid_dump(std::string_view text) {
  check_size(text);
  DumpReader reader;
  for (const Line& line : lines_of(text)) reader.line(line);
  return reader.finish();
}

RecordingFormat detect_format(std::string_view contents) {
  bool hex_only = !contents.empty();
  for (const Line& line : lines_of(contents.substr(0, 1 << 16))) {
    const auto tokens = tokens_of(line);
    if (tokens.empty()) continue;
    const auto t = tokens[0].text;
    if (t == "R:" || t == "E:" || t == "N:" || t == "I:" || t == "P:") {
      return RecordingFormat::kHidRecorder;
    }
    if (t.ends_with(":STREAM") || t.ends_with(":DESCRIPTOR")) return RecordingFormat::kUsbhidDump;
    for (const auto& tok : tokens) {
      if (tok.text.size() != 2 || hex_digit(tok.text[0]) < 0 || hex_digit(tok.text[1]) < 0) {
        hex_only = false;
      }
    }
    if (t.front() == '#') continue;
  }
  return hex_only ? RecordingFormat::kUsbhidDump : RecordingFormat::kRawBytes;
}

Recording recording_from_dump(const UsbhidDump& dump, int interface, const DeviceIdentity& id) {
  Recording r;
  r.identity = id;
  r.has_identity = id.vendor_id != 0 || id.product_id != 0;
  if (const auto it = dump.descriptors.find(interface); it != dump.descriptors.end()) {
    r.descriptor = it->second;
  }
  if (const auto it = dump.streams.find(interface); it != dump.streams.end()) {
    r.events = it->second;
  }
  return r;
}

Recording load_recording_file(const std::filesystem::path& path) {
  const std::string text = read_file(path);
  switch (detect_format(text)) {
    case RecordingFormat::kHidRecorder:
      return read_hid_recorder(text);
    case RecordingFormat::kUsbhidDump: {
      const UsbhidDump dump = read_usbhid_dump(text);
      int iface = dump.descriptors.empty() ? 0 : dump.descriptors.begin()->first;
      // Descriptors only: the first interface whose descriptor declares a pen.
      for (const auto& [i, bytes] : dump.descriptors) {
        try {
          if (!find_pen_layouts(parse_report_descriptor(bytes)).empty()) {
            iface = i;
            break;
          }
        } catch (const DescriptorError&) {
        }
      }
      std::size_t most = 0;
      for (const auto& [i, events] : dump.streams) {
        if (events.size() > most) {
          most = events.size();
          iface = i;
        }
      }
      return recording_from_dump(dump, iface, {});
    }
    case RecordingFormat::kRawBytes:
      break;
  }
  Recording r;
  r.descriptor.assign(text.begin(), text.end());
  return r;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RecordingError(0, "cannot open " + path.string());
  in.seekg(0, std::ios::end);
  const auto size = in.tellg();
  if (size < 0) throw RecordingError(0, "cannot read " + path.string());
  if (static_cast<std::uint64_t>(size) > kMaxRecordingBytes) {
    throw RecordingError(kMaxRecordingBytes, path.string() + " is larger than 256 MiB");
  }
  std::string out(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  in.read(out.data(), size);
  if (!in) throw RecordingError(0, "cannot read " + path.string());
  return out;
}

} // namespace penshape::drivers
