// Parses drivers/data/families.tsv (the report-family notation documented at its top) into pen
// layouts, and fills a family's layouts with a tablet row's maxima.
#include "penshape/drivers/report_families.hpp"

#include <charconv>

#include "tsv_rows.hpp"

namespace penshape::drivers {

std::string_view builtin_family_tsv(); // generated from data/families.tsv (families_tsv.cpp.in)

namespace {

// One line's context for error messages.
struct Where {
  std::size_t line = 0;
  std::string_view token;
  [[noreturn]] void fail(const std::string& what) const {
    throw FamilyTableError("report family table line " + std::to_string(line) + ": " + what +
                           " in '" + std::string(token) + "'");
  }
};

template <typename T>
T number(std::string_view s, int base, const Where& w) {
  T v{};
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v, base);
  if (s.empty() || r.ec != std::errc{} || r.ptr != s.data() + s.size()) w.fail("bad number");
  return v;
}

// "byte[.bit]" -> bit offset.
std::uint32_t bit_position(std::string_view s, const Where& w) {
  const auto dot = s.find('.');
  const auto byte = number<std::uint32_t>(s.substr(0, dot), 10, w);
  const std::uint32_t bit =
      dot == std::string_view::npos ? 0 : number<std::uint32_t>(s.substr(dot + 1), 10, w);
  if (bit > 7 || byte > 4095) w.fail("bit position out of range");
  return byte * 8 + bit;
}

// "byte[.bit]:bits[be],..." (at most three pieces, least significant first; 's' suffix signed).
PenField value_field(std::string_view spec, const Where& w) {
  PenField f;
  if (!spec.empty() && spec.back() == 's') {
    f.is_signed = true;
    spec.remove_suffix(1);
  }
  const auto pieces = tsv::split(spec, ',', tsv::Empty::kSkip);
  if (pieces.empty() || pieces.size() > 3) w.fail("a value needs one to three pieces");
  std::uint32_t* offsets[] = {&f.bit_offset, &f.high_bit_offset, &f.top_bit_offset};
  std::uint32_t* sizes[] = {&f.bit_size, &f.high_bit_size, &f.top_bit_size};
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    std::string_view p = pieces[i];
    const bool be = p.size() > 2 && p.substr(p.size() - 2) == "be";
    if (be) p.remove_suffix(2);
    const auto colon = p.find(':');
    if (colon == std::string_view::npos) w.fail("a piece needs byte:bits");
    *offsets[i] = bit_position(p.substr(0, colon), w);
    *sizes[i] = number<std::uint32_t>(p.substr(colon + 1), 10, w);
    if (*sizes[i] == 0 || *sizes[i] > 24) w.fail("a piece has 1 to 24 bits");
    if (be && (i != 1 || *sizes[i] % 8 != 0)) w.fail("only a whole-byte second piece is 'be'");
    if (be) f.high_big_endian = true;
  }
  if (f.total_bits() > 32) w.fail("a value has at most 32 bits");
  const std::uint32_t bits = f.total_bits();
  if (f.is_signed) {
    f.logical_minimum = -static_cast<std::int32_t>((1U << (bits - 1)) - 0U);
    f.logical_maximum = static_cast<std::int32_t>((1U << (bits - 1)) - 1U);
  } else {
    f.logical_maximum = bits >= 31 ? 0x7FFFFFFF : static_cast<std::int32_t>((1U << bits) - 1U);
  }
  return f;
}

// "[!]byte.bit".
PenField flag_field(std::string_view spec, const Where& w) {
  PenField f;
  if (!spec.empty() && spec.front() == '!') {
    f.inverted = true;
    spec.remove_prefix(1);
  }
  f.bit_offset = bit_position(spec, w);
  f.bit_size = 1;
  f.logical_maximum = 1;
  return f;
}

// "B&MM==VV" or "B&MM!=VV".
void match(std::string_view spec, std::uint32_t& byte, std::uint8_t& mask, std::uint8_t& value,
           bool& reject, const Where& w) {
  const auto amp = spec.find('&');
  const auto op = spec.find_first_of("=!", amp == std::string_view::npos ? 0 : amp);
  if (amp == std::string_view::npos || op == std::string_view::npos || op + 2 > spec.size() ||
      spec[op + 1] != '=') {
    w.fail("a match is byte&mask==value or byte&mask!=value");
  }
  byte = number<std::uint32_t>(spec.substr(0, amp), 10, w);
  mask = number<std::uint8_t>(spec.substr(amp + 1, op - amp - 1), 16, w);
  value = number<std::uint8_t>(spec.substr(op + 2), 16, w);
  reject = spec[op] == '!';
  if (mask == 0 || (value & ~mask) != 0) w.fail("match value outside its mask");
}

double real(std::string_view s, const Where& w) {
  try {
    std::size_t used = 0;
    const double v = std::stod(std::string(s), &used);
    if (used != s.size()) w.fail("bad number");
    return v;
  } catch (const std::logic_error&) {
    w.fail("bad number");
  }
}

struct Tilt {
  double scale = 1.0;
  double offset = 0.0;
};

void apply_token(PenLayout& l, Tilt& tilt, std::string_view key, std::string_view v,
                 const Where& w) {
  if (key == "id") {
    l.uses_report_id = true;
    if (v == "*") {
      l.any_report_id = true;
    } else {
      l.report_id = number<std::uint8_t>(v, 16, w);
    }
  } else if (key == "len") {
    l.min_report_bytes = number<std::uint32_t>(v, 10, w);
  } else if (key == "match") {
    match(v, l.match_byte, l.match_mask, l.match_value, l.match_reject, w);
  } else if (key == "match2") {
    match(v, l.match2_byte, l.match2_mask, l.match2_value, l.match2_reject, w);
  } else if (key == "x") {
    l.x = value_field(v, w);
  } else if (key == "y") {
    l.y = value_field(v, w);
  } else if (key == "p") {
    l.pressure = value_field(v, w);
  } else if (key == "tx") {
    l.tilt_x = value_field(v, w);
  } else if (key == "ty") {
    l.tilt_y = value_field(v, w);
  } else if (key == "tip") {
    l.tip = flag_field(v, w);
  } else if (key == "range") {
    l.in_range = flag_field(v, w);
  } else if (key == "b1") {
    l.barrel1 = flag_field(v, w);
  } else if (key == "b2") {
    l.barrel2 = flag_field(v, w);
  } else if (key == "b3") {
    l.barrel3 = flag_field(v, w);
  } else if (key == "eraser") {
    l.eraser = flag_field(v, w);
  } else if (key == "tiltoff") {
    tilt.offset = real(v, w);
  } else if (key == "tiltscale") {
    tilt.scale = real(v, w);
  } else if (key == "tipth") {
    l.tip_pressure_threshold = number<std::uint32_t>(v, 10, w);
  } else {
    w.fail("unknown key");
  }
}

PenLayout parse_layout(std::string_view family, std::string_view spec, std::size_t line) {
  PenLayout l;
  l.origin = std::string(family);
  Tilt tilt;
  for (std::string_view token : tsv::split(spec, ' ', tsv::Empty::kSkip)) {
    const Where w{line, token};
    const auto eq = token.find('=');
    if (eq == std::string_view::npos) w.fail("expected key=value");
    apply_token(l, tilt, token.substr(0, eq), token.substr(eq + 1), w);
  }
  const Where w{line, spec};
  if (!l.uses_report_id) w.fail("a layout needs id=");
  if (!l.x.present() || !l.y.present()) w.fail("a layout needs x= and y=");
  if (l.tilt_x.present() != l.tilt_y.present()) w.fail("tx= and ty= go together");
  if (l.min_report_bytes == 0) w.fail("a layout needs len=");
  // Degrees = (value - min) * scale + offset, so a signed value reads as itself times scale.
  l.tilt_scale = tilt.scale;
  l.tilt_offset = l.tilt_x.logical_minimum * tilt.scale + tilt.offset;
  return l;
}

// Moves every byte position `bytes` later (a driver that prefixes bytes to each report): the
// report's own ID then sits at byte `bytes`, and byte 0 is whatever the driver put there.
void shift_layout(PenLayout& l, std::uint32_t bytes, const Where& w) {
  if (bytes == 0) return;
  const std::uint32_t bits = bytes * 8;
  for (PenField* f : {&l.tip, &l.in_range, &l.barrel1, &l.barrel2, &l.barrel3, &l.eraser, &l.invert,
                      &l.x, &l.y, &l.pressure, &l.tilt_x, &l.tilt_y}) {
    if (!f->present()) continue;
    f->bit_offset += bits;
    if (f->high_bit_size > 0) f->high_bit_offset += bits;
    if (f->top_bit_size > 0) f->top_bit_offset += bits;
  }
  if (l.match_mask != 0) l.match_byte += bytes;
  if (l.match2_mask != 0) l.match2_byte += bytes;
  l.min_report_bytes += bytes;
  if (l.any_report_id) return;
  l.any_report_id = true;
  if (l.match_mask == 0) {
    l.match_byte = bytes;
    l.match_mask = 0xFF;
    l.match_value = l.report_id;
    l.match_reject = false;
  } else if (l.match2_mask == 0) {
    l.match2_byte = bytes;
    l.match2_mask = 0xFF;
    l.match2_value = l.report_id;
    l.match2_reject = false;
  } else {
    w.fail("a shifted layout needs a free match for its report ID");
  }
}

// "@base [shift=N]": the layouts of an earlier family.
std::vector<PenLayout> alias_layouts(std::string_view spec, std::string_view name,
                                     const std::vector<ReportFamily>& known, std::size_t line) {
  const auto tokens = tsv::split(spec, ' ', tsv::Empty::kSkip);
  const Where w{line, spec};
  const ReportFamily* base = nullptr;
  for (const auto& f : known) {
    if (f.name == tokens[0].substr(1)) base = &f;
  }
  if (base == nullptr) w.fail("unknown base family (define it above)");
  std::uint32_t shift = 0;
  for (std::size_t i = 1; i < tokens.size(); ++i) {
    if (tokens[i].substr(0, 6) != "shift=") w.fail("only shift= may follow @base");
    shift = number<std::uint32_t>(tokens[i].substr(6), 10, w);
  }
  std::vector<PenLayout> out = base->layouts;
  for (auto& l : out) {
    shift_layout(l, shift, w);
    l.origin = std::string(name);
  }
  return out;
}

} // namespace

std::vector<ReportFamily> parse_report_families(std::string_view tsv) {
  std::vector<ReportFamily> out;
  tsv::for_each_row(
      tsv, tsv::Empty::kSkip,
      [&](std::size_t line_no, std::string_view line, const std::vector<std::string_view>& cols) {
        const Where w{line_no, line};
        if (cols.size() != 3) w.fail("expected 3 tab-separated columns");
        const auto protocol = protocol_from_name(cols[1]);
        if (!protocol) w.fail("unknown protocol");
        ReportFamily* family = nullptr;
        for (auto& f : out) {
          if (f.name == cols[0]) family = &f;
        }
        if (family == nullptr) {
          out.push_back(ReportFamily{std::string(cols[0]), *protocol, {}});
          family = &out.back();
        } else if (family->protocol != *protocol) {
          w.fail("a family has one protocol");
        }
        if (cols[2] == "-") return;
        if (cols[2].front() == '@') {
          for (auto& l : alias_layouts(cols[2], cols[0], out, line_no)) {
            family->layouts.push_back(std::move(l));
          }
        } else {
          family->layouts.push_back(parse_layout(cols[0], cols[2], line_no));
        }
      });
  return out;
}

const std::vector<ReportFamily>& builtin_families() {
  static const std::vector<ReportFamily> families = parse_report_families(builtin_family_tsv());
  return families;
}

const ReportFamily* find_family(std::string_view name) {
  for (const auto& f : builtin_families()) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

std::vector<PenLayout> family_layouts(const ReportFamily& family, const TabletSpec& spec) {
  if (spec.x_max <= 0 || spec.y_max <= 0) return {};
  std::vector<PenLayout> out = family.layouts;
  for (auto& l : out) {
    l.x.logical_maximum = spec.x_max;
    l.y.logical_maximum = spec.y_max;
    if (l.pressure.present()) {
      l.pressure.logical_maximum = static_cast<std::int32_t>(spec.pressure_max);
    }
    l.x_resolution = spec.x_resolution;
    l.y_resolution = spec.y_resolution;
  }
  return out;
}

} // namespace penshape::drivers
