#include "penshape/drivers/pen_layout.hpp"

#include <cmath>
#include <optional>

#include "penshape/types/lookup_table.hpp"

namespace penshape::drivers {
namespace {

constexpr std::uint16_t kDesktop = 0x01;
constexpr std::uint16_t kDigitizer = 0x0D;
constexpr std::uint16_t kButton = 0x09;

PenField field_from(const ReportField& f) {
  PenField p;
  p.bit_offset = f.bit_offset;
  p.bit_size = std::min<std::uint32_t>(f.bit_size, 32);
  p.is_signed = f.is_signed();
  p.logical_minimum = f.logical_minimum;
  p.logical_maximum = f.logical_maximum;
  return p;
}

// HID units: nibble 0 is the system (1 SI linear, 2 SI rotation, 3 English linear, 4 English
// rotation), nibble 1 the length (or rotation) exponent.
double degrees_per_unit(const ReportField& f) {
  const std::uint32_t system = f.unit & 0xF;
  const std::uint32_t length_exp = (f.unit >> 4) & 0xF;
  if (length_exp != 1) return 0.0;
  const double scale = std::pow(10.0, f.unit_exponent);
  if (system == 4) return scale;                // degrees
  if (system == 2) return scale * 180.0 / M_PI; // radians
  return 0.0;
}

bool is_pen_application(Usage app) {
  return app == make_usage(kDigitizer, 0x01) || app == make_usage(kDigitizer, 0x02);
}

struct Candidate {
  const ReportField* x = nullptr;
  const ReportField* y = nullptr;
  const ReportField* tip = nullptr;
  const ReportField* in_range = nullptr;
  const ReportField* pressure = nullptr;
  const ReportField* tilt_x = nullptr;
  const ReportField* tilt_y = nullptr;
  const ReportField* eraser = nullptr;
  const ReportField* invert = nullptr;
  std::vector<const ReportField*> barrels;
  std::vector<const ReportField*> buttons; // Button page 1..3 (mouse-mode pens)
  bool stylus_collection = false;
  bool finger_collection = false;
  Usage application = 0;
};

void take(const ReportField*& slot, const ReportField& f) {
  if (slot == nullptr) slot = &f;
}

} // namespace

double resolution_per_mm(const ReportField& axis) {
  const std::uint32_t system = axis.unit & 0xF;
  const std::uint32_t length_exp = (axis.unit >> 4) & 0xF;
  if (length_exp != 1 || (system != 1 && system != 3)) return 0.0;
  const double span_phys = static_cast<double>(axis.physical_maximum) - axis.physical_minimum;
  const double span_log = static_cast<double>(axis.logical_maximum) - axis.logical_minimum;
  if (span_phys <= 0 || span_log <= 0) return 0.0;
  const double mm_per_unit = system == 1 ? 10.0 : 25.4; // centimetre or inch
  const double size_mm = span_phys * std::pow(10.0, axis.unit_exponent) * mm_per_unit;
  return size_mm > 0 ? span_log / size_mm : 0.0;
}

namespace {

// The digitizer-page usages a pen report carries, each to its slot in the candidate: tip switch,
// in range, tip pressure, X and Y tilt, eraser, invert; barrel switches (1 and 2) are collected.
void file_digitizer_field(Candidate& c, const ReportField& f, std::uint16_t id) {
  using Slot = const ReportField* Candidate::*;
  static constexpr LookupTable<std::uint16_t, Slot, 7> kSlots{{{0x42, &Candidate::tip},
                                                               {0x32, &Candidate::in_range},
                                                               {0x30, &Candidate::pressure},
                                                               {0x3D, &Candidate::tilt_x},
                                                               {0x3E, &Candidate::tilt_y},
                                                               {0x45, &Candidate::eraser},
                                                               {0x3C, &Candidate::invert}}};
  if (const Slot slot = lookup_or(kSlots, id, nullptr)) {
    take(c.*slot, f);
  } else if (id == 0x44 || id == 0x5A) {
    c.barrels.push_back(&f);
  }
}

void file_field(Candidate& c, const ReportField& f) {
  if (f.collection == make_usage(kDigitizer, 0x20)) c.stylus_collection = true;
  if (f.collection == make_usage(kDigitizer, 0x22)) c.finger_collection = true;
  if (c.application == 0) c.application = f.application;
  if (f.is_constant() || !f.is_variable()) return;
  const std::uint16_t page = usage_page(f.usage);
  const std::uint16_t id = usage_id(f.usage);
  if (page == kDesktop && !f.is_relative()) {
    if (id == 0x30) take(c.x, f);
    if (id == 0x31) take(c.y, f);
  } else if (page == kDigitizer) {
    file_digitizer_field(c, f, id);
  } else if (page == kButton && id >= 1 && id <= 3) {
    c.buttons.push_back(&f);
  }
}

enum class PenKind { kNone, kPen, kMouseMode };

// A pen report has a position and a contact signal, and is not a touch-only collection: a pen
// application or stylus collection, or a mouse-mode report with pressure and buttons.
PenKind pen_kind(const Candidate& c) {
  if (c.x == nullptr || c.y == nullptr) return PenKind::kNone;
  if (c.tip == nullptr && c.pressure == nullptr && c.in_range == nullptr) return PenKind::kNone;
  if (c.finger_collection && !c.stylus_collection) return PenKind::kNone;
  if (is_pen_application(c.application) || c.stylus_collection) return PenKind::kPen;
  if (c.pressure != nullptr && !c.buttons.empty()) return PenKind::kMouseMode;
  return PenKind::kNone;
}

void set_tilt(PenLayout& l, const ReportField& tilt_x, const ReportField& tilt_y) {
  l.tilt_x = field_from(tilt_x);
  l.tilt_y = field_from(tilt_y);
  const double deg = degrees_per_unit(tilt_x);
  const double span_log = static_cast<double>(tilt_x.logical_maximum) - tilt_x.logical_minimum;
  const double span_phys = static_cast<double>(tilt_x.physical_maximum) - tilt_x.physical_minimum;
  if (deg > 0 && span_log > 0 && span_phys > 0) {
    l.tilt_scale = span_phys / span_log * deg;
    l.tilt_offset = tilt_x.physical_minimum * deg;
  } else {
    // No angular unit: the common vendor convention is whole degrees, signed.
    l.tilt_scale = 1.0;
    l.tilt_offset = tilt_x.logical_minimum;
  }
}

// Mouse-mode pens report the tip as button 1 and the barrel buttons as 2 and 3.
void set_buttons(PenLayout& l, const Candidate& c) {
  std::vector<const ReportField*> barrels = c.barrels;
  if (c.tip == nullptr) {
    for (const auto* b : c.buttons) {
      if (usage_id(b->usage) == 1) {
        l.tip = field_from(*b);
      } else {
        barrels.push_back(b);
      }
    }
  }
  if (!barrels.empty()) l.barrel1 = field_from(*barrels[0]);
  if (barrels.size() > 1) l.barrel2 = field_from(*barrels[1]);
  if (barrels.size() > 2) l.barrel3 = field_from(*barrels[2]);
}

PenLayout layout_from(const Candidate& c, const ReportLayout& report, bool uses_report_ids) {
  PenLayout l;
  l.origin = "hid";
  l.report_id = report.report_id;
  l.uses_report_id = uses_report_ids;
  l.min_report_bytes = report.size_bytes();
  l.x = field_from(*c.x);
  l.y = field_from(*c.y);
  if (c.tip) l.tip = field_from(*c.tip);
  if (c.in_range) l.in_range = field_from(*c.in_range);
  if (c.pressure) l.pressure = field_from(*c.pressure);
  if (c.eraser) l.eraser = field_from(*c.eraser);
  if (c.invert) l.invert = field_from(*c.invert);
  if (c.tilt_x && c.tilt_y) set_tilt(l, *c.tilt_x, *c.tilt_y);
  set_buttons(l, c);
  l.x_resolution = resolution_per_mm(*c.x);
  l.y_resolution = resolution_per_mm(*c.y);
  return l;
}

} // namespace

// Digitizer reports first, then mouse-mode ones, each in descriptor order.
std::vector<PenLayout> find_pen_layouts(const ParsedDescriptor& descriptor) {
  std::vector<PenLayout> digitizer;
  std::vector<PenLayout> mouse_mode;
  for (const auto& report : descriptor.reports) {
    if (report.type != ReportType::kInput) continue;
    Candidate c;
    for (const auto& f : report.fields) file_field(c, f);
    const PenKind kind = pen_kind(c);
    if (kind == PenKind::kNone) continue;
    (kind == PenKind::kPen ? digitizer : mouse_mode)
        .push_back(layout_from(c, report, descriptor.uses_report_ids));
  }
  for (auto& l : mouse_mode) digitizer.push_back(std::move(l));
  return digitizer;
}

void apply_layout(const PenLayout& layout, TabletInfo& info) {
  info.x_max = layout.x_max();
  info.y_max = layout.y_max();
  info.pressure_max = layout.pressure_max();
  info.x_resolution = layout.x_resolution;
  info.y_resolution = layout.y_resolution;
  info.has_tilt = layout.tilt_x.present() && layout.tilt_y.present();
}

} // namespace penshape::drivers
