// Chooses a device's table row, report family, layouts and physical size (build_profile).
#include "penshape/drivers/device_profile.hpp"

#include <algorithm>

#include "penshape/drivers/pen_layout.hpp"
#include "penshape/drivers/report_families.hpp"
#include "penshape/drivers/vendor_protocols.hpp"
#include "penshape/types/lookup_table.hpp"

namespace penshape::drivers {
namespace {

bool describes(const std::vector<PenLayout>& layouts, std::uint8_t report_id) {
  return std::any_of(layouts.begin(), layouts.end(),
                     [&](const PenLayout& l) { return l.report_id == report_id; });
}

// Vendors whose unknown models still answer the UC-Logic probe (string descriptor 200).
bool uclogic_vendor(std::uint16_t vid) { return vid == 0x256c || vid == 0x5543; }

std::vector<std::uint32_t> input_report_lengths(const std::optional<ParsedDescriptor>& d) {
  std::vector<std::uint32_t> out;
  if (!d) return out;
  for (const auto& r : d->reports) {
    if (r.type == ReportType::kInput) out.push_back(r.size_bytes());
  }
  return out;
}

DeviceStrings strings_text(const VendorStrings& raw) {
  DeviceStrings out;
  for (const auto& [index, bytes] : raw) out[index] = string_descriptor_text(bytes);
  return out;
}

// The family's layouts for a row whose maxima (and size) come from a UC-Logic probe.
std::vector<PenLayout> probed_layouts(const ReportFamily& family, const TabletSpec* row,
                                      const UcLogicParams& p) {
  TabletSpec probed = row != nullptr ? *row : TabletSpec{};
  probed.x_max = p.x_max;
  probed.y_max = p.y_max;
  probed.pressure_max = p.pressure_max;
  probed.x_resolution = p.resolution_lpi / 25.4;
  probed.y_resolution = probed.x_resolution;
  return family_layouts(family, probed);
}

struct VendorChoice {
  std::vector<PenLayout> layouts;
  bool probed = false;
};

// UC-Logic: the parameters of string descriptor 200 (v2: the family's layouts) or 100 (v1),
// else the table's maxima.
VendorChoice uclogic_layouts(const ReportFamily& family, const TabletSpec* row,
                             bool descriptor_has_pen, const VendorStrings& strings,
                             std::vector<std::string>& notes) {
  for (const std::uint8_t index : {std::uint8_t{200}, std::uint8_t{100}}) {
    const auto it = strings.find(index);
    if (it == strings.end()) continue;
    const UcLogicParams p = parse_uclogic_params(it->second, index == 200 ? 2 : 1);
    notes.push_back("UC-Logic parameters from string descriptor " + std::to_string(index));
    if (index == 100) return {{uclogic_pen_layout(p)}, true};
    return {probed_layouts(family, row, p), true};
  }
  // Not probed: the tablet stays in firmware mode, whose reports its descriptor describes; the
  // table's maxima only serve a descriptor without a pen.
  if (row != nullptr && row->pressure_max > 0 && !descriptor_has_pen) {
    notes.push_back("UC-Logic vendor layout with the tablet table's maxima");
    return {family_layouts(family, *row), false};
  }
  return {};
}

// The vendor layouts the protocol calls for, before checking them against the descriptor.
VendorChoice vendor_layouts(DeviceProfile& out, const ReportFamily& family, const TabletSpec* row,
                            bool descriptor_has_pen, const VendorStrings& strings) {
  const auto table = [&] {
    return row != nullptr ? family_layouts(family, *row) : std::vector<PenLayout>{};
  };
  switch (out.protocol) {
    case Protocol::kHid:
      return {};
    case Protocol::kWacomHid:
      out.init = row->init;
      out.notes.push_back("Wacom mode switch (feature report) at open; descriptor pens");
      return {};
    case Protocol::kWacomGraphire:
      return {table(), false};
    case Protocol::kWacomBamboo:
    case Protocol::kWacomIntuos:
      out.init = row->init;
      if (descriptor_has_pen) return {};
      out.notes.push_back("Wacom mode switch (feature report) at open; " + family.name +
                          " pen packets");
      return {table(), false};
    case Protocol::kUcLogic:
      if (row != nullptr) out.init = row->init;
      return uclogic_layouts(family, row, descriptor_has_pen, strings, out.notes);
    case Protocol::kXpPen:
      if (descriptor_has_pen) return {};
      out.init = row->init;
      out.notes.push_back("XP-Pen vendor mode (output report) at open");
      return {table(), false};
    case Protocol::kVendor: {
      // A descriptor that describes a pen is the device's own word (its firmware mode, or a
      // capture's synthetic descriptor); the vendor layouts serve a descriptor without one.
      if (descriptor_has_pen) return {};
      out.init = row->init;
      auto layouts = table();
      if (!layouts.empty()) out.notes.push_back(family.name + " vendor reports");
      return {std::move(layouts), false};
    }
  }
  return {};
}

// Resolution of the primary layout: the descriptor's or the probe's own, else the table's
// physical size over the layout's own maxima (a firmware-mode descriptor may count in other
// units than the table's vendor mode), else unknown.
void choose_size(DeviceProfile& out, bool vendor_primary, bool probed) {
  if (out.info.x_resolution > 0 && out.info.y_resolution > 0) {
    out.size_source = probed && vendor_primary
                          ? SizeSource::kProbe
                          : (vendor_primary ? SizeSource::kTable : SizeSource::kDescriptor);
    return;
  }
  if (out.spec != nullptr && out.spec->width_mm > 0 && out.spec->height_mm > 0 &&
      out.info.x_max > 0 && out.info.y_max > 0) {
    out.info.x_resolution = out.info.x_max / out.spec->width_mm;
    out.info.y_resolution = out.info.y_max / out.spec->height_mm;
    out.size_source = SizeSource::kTable;
    return;
  }
  out.info.x_resolution = 0;
  out.info.y_resolution = 0;
  out.size_source = SizeSource::kUnknown;
  out.notes.push_back("physical size unknown: coordinates are device units, not millimetres");
}

} // namespace

std::string_view size_source_name(SizeSource s) {
  static constexpr LookupTable<SizeSource, std::string_view, 5> kNames{
      {{SizeSource::kUnknown, "unknown"},
       {SizeSource::kTable, "table"},
       {SizeSource::kDescriptor, "descriptor"},
       {SizeSource::kProbe, "probe"},
       {SizeSource::kConfig, "config"}}};
  return lookup_or(kNames, s, "?");
}

std::vector<std::uint8_t> vendor_string_indexes(Protocol p) {
  if (p == Protocol::kUcLogic) return {200, 100};
  return {};
}

std::vector<std::uint8_t> vendor_string_indexes(std::uint16_t vendor_id, std::uint16_t product_id) {
  const auto rows = find_tablets(vendor_id, product_id);
  std::vector<std::uint8_t> out;
  const auto add = [&](std::uint8_t i) {
    if (std::find(out.begin(), out.end(), i) == out.end()) out.push_back(i);
  };
  if (rows.empty() && uclogic_vendor(vendor_id)) return {200, 100};
  for (const TabletSpec* r : rows) {
    for (const std::uint8_t i : vendor_string_indexes(r->protocol)) add(i);
  }
  for (const std::uint8_t i : device_match_indexes(vendor_id, product_id)) add(i);
  return out;
}

bool apply_configured_size(DeviceProfile& profile, double width_mm, double height_mm) {
  if (profile.size_source != SizeSource::kUnknown || !(width_mm > 0) || !(height_mm > 0) ||
      profile.info.x_max <= 0 || profile.info.y_max <= 0) {
    return false;
  }
  profile.info.x_resolution = profile.info.x_max / width_mm;
  profile.info.y_resolution = profile.info.y_max / height_mm;
  profile.size_source = SizeSource::kConfig;
  return true;
}

DeviceProfile build_profile(const DeviceIdentity& id, std::span<const std::uint8_t> descriptor,
                            const VendorStrings& vendor_strings) {
  DeviceProfile out;
  std::vector<PenLayout> from_descriptor;
  if (!descriptor.empty()) {
    out.descriptor = parse_report_descriptor(descriptor);
    from_descriptor = find_pen_layouts(*out.descriptor);
  }
  const DeviceStrings text = strings_text(vendor_strings);
  const auto lengths = input_report_lengths(out.descriptor);
  out.spec =
      match_tablet(id.vendor_id, id.product_id, vendor_strings.empty() ? nullptr : &text, lengths);
  const ReportFamily* family = find_family(out.spec != nullptr ? out.spec->family : "hid");
  if (out.spec == nullptr && uclogic_vendor(id.vendor_id) &&
      (vendor_strings.count(200) != 0 || vendor_strings.count(100) != 0)) {
    family = find_family("uclogic"); // a Huion/Gaomon model we have no row for: probe it
    out.notes.push_back("no table row; UC-Logic probe by vendor ID");
  }
  out.family = family->name;
  out.protocol = family->protocol;

  VendorChoice vendor =
      vendor_layouts(out, *family, out.spec, !from_descriptor.empty(), vendor_strings);
  // A kernel driver (hid-uclogic) that rewrote the descriptor already describes the vendor
  // report: the descriptor wins for the whole family.
  for (const auto& l : vendor.layouts) {
    if (!l.any_report_id && describes(from_descriptor, l.report_id)) {
      out.notes.push_back("descriptor already describes vendor report " +
                          std::to_string(l.report_id) + " (kernel driver rewrote it)");
      vendor.layouts.clear();
      break;
    }
  }
  std::vector<PenLayout> layouts = std::move(vendor.layouts);
  const bool vendor_primary = !layouts.empty();
  if (vendor_primary) {
    // Keep descriptor pens only when they agree on report IDs (a report-ID-less descriptor
    // cannot share a stream with an ID-prefixed vendor report).
    for (auto& l : from_descriptor) {
      if (l.uses_report_id) layouts.push_back(std::move(l));
    }
  } else {
    layouts = std::move(from_descriptor);
  }
  if (layouts.empty()) out.notes.push_back("no pen report found");

  out.info.bus = id.bus;
  out.info.vendor_id = id.vendor_id;
  out.info.product_id = id.product_id;
  out.info.name = !id.name.empty() ? id.name : (out.spec != nullptr ? out.spec->name : "");
  if (!layouts.empty()) {
    apply_layout(layouts.front(), out.info);
    choose_size(out, vendor_primary, vendor.probed);
  }
  out.decoder = PenDecoder(std::move(layouts), out.descriptor ? &*out.descriptor : nullptr);
  return out;
}

} // namespace penshape::drivers
