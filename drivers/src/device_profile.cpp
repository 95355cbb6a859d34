#include "penshape/drivers/device_profile.hpp"

#include <algorithm>

#include "penshape/drivers/pen_layout.hpp"
#include "penshape/drivers/vendor_protocols.hpp"

namespace penshape::drivers {
namespace {

bool describes(const std::vector<PenLayout>& layouts, std::uint8_t report_id) {
  return std::any_of(layouts.begin(), layouts.end(),
                     [&](const PenLayout& l) { return l.report_id == report_id; });
}

} // namespace

std::vector<std::uint8_t> vendor_string_indexes(Protocol p) {
  if (p == Protocol::kUcLogic) return {200, 100};
  return {};
}

DeviceProfile build_profile(const DeviceIdentity& id, std::span<const std::uint8_t> descriptor,
                            const VendorStrings& vendor_strings) {
  DeviceProfile out;
  std::vector<PenLayout> from_descriptor;
  if (!descriptor.empty()) {
    out.descriptor = parse_report_descriptor(descriptor);
    from_descriptor = find_pen_layouts(*out.descriptor);
  }
  const TabletSpec* spec = find_tablet(id.vendor_id, id.product_id);
  out.protocol = spec != nullptr ? spec->protocol : Protocol::kHid;

  // A plain value plus flag: GCC 12 misreports std::optional<PenLayout> as uninitialised.
  PenLayout vendor;
  bool have_vendor = false;
  std::vector<PenLayout> extra_vendor; // protocols with several layouts (all share one ID)
  switch (out.protocol) {
    case Protocol::kHid:
      break;
    case Protocol::kWacomHid:
      out.init = spec->init;
      out.notes.push_back("Wacom mode switch (feature report) at open; descriptor pens");
      break;
    case Protocol::kWacomGraphire:
      if (spec->x_max > 0) {
        vendor = wacom_graphire_pen_layout(*spec);
        have_vendor = true;
      }
      break;
    case Protocol::kWacomBamboo:
      out.init = spec->init;
      if (from_descriptor.empty() && spec->x_max > 0) {
        vendor = wacom_bamboo_pen_layout(*spec);
        have_vendor = true;
        out.notes.push_back("Wacom mode switch (feature report) at open; Bamboo pen reports");
      }
      break;
    case Protocol::kWacomIntuos:
      out.init = spec->init;
      if (from_descriptor.empty() && spec->x_max > 0) {
        for (auto& l : wacom_intuos_pen_layouts(*spec)) extra_vendor.push_back(std::move(l));
        out.notes.push_back("Wacom mode switch (feature report) at open; Intuos pen packets");
      }
      break;
    case Protocol::kUcLogic: {
      out.init = spec->init;
      for (const std::uint8_t index : vendor_string_indexes(out.protocol)) {
        const auto it = vendor_strings.find(index);
        if (it == vendor_strings.end()) continue;
        vendor = uclogic_pen_layout(parse_uclogic_params(it->second, index == 200 ? 2 : 1));
        have_vendor = true;
        out.notes.push_back("UC-Logic parameters from string descriptor " + std::to_string(index));
        break;
      }
      if (!have_vendor && spec->x_max > 0 && spec->pressure_max > 0) {
        UcLogicParams p;
        p.x_max = spec->x_max;
        p.y_max = spec->y_max;
        p.pressure_max = spec->pressure_max;
        p.resolution_lpi = static_cast<std::uint32_t>(spec->x_resolution * 25.4 + 0.5);
        vendor = uclogic_pen_layout(p);
        have_vendor = true;
        out.notes.push_back("UC-Logic vendor layout with the tablet table's maxima");
      }
      break;
    }
    case Protocol::kXpPen:
      if (from_descriptor.empty() && spec->x_max > 0) {
        vendor = xppen_pen_layout(*spec);
        have_vendor = true;
        out.init = spec->init;
        out.notes.push_back("XP-Pen vendor mode (output report) at open");
      }
      break;
  }

  std::vector<PenLayout> layouts;
  if (have_vendor && describes(from_descriptor, vendor.report_id)) {
    out.notes.push_back("descriptor already describes vendor report " +
                        std::to_string(vendor.report_id) + " (kernel driver rewrote it)");
    have_vendor = false;
  }
  if (have_vendor) {
    vendor.uses_report_id = true;
    layouts.push_back(vendor);
    // Keep descriptor pens only when they agree on report IDs (a report-ID-less descriptor
    // cannot share a stream with an ID-prefixed vendor report).
    for (auto& l : from_descriptor) {
      if (l.uses_report_id) layouts.push_back(std::move(l));
    }
  } else {
    layouts = std::move(from_descriptor);
  }
  if (!extra_vendor.empty()) {
    layouts.insert(layouts.begin(), extra_vendor.begin(), extra_vendor.end());
  }
  if (layouts.empty()) out.notes.push_back("no pen report found");

  out.info.bus = id.bus;
  out.info.vendor_id = id.vendor_id;
  out.info.product_id = id.product_id;
  out.info.name = !id.name.empty() ? id.name : (spec != nullptr ? spec->name : std::string());
  if (!layouts.empty()) {
    apply_layout(layouts.front(), out.info);
    if (out.info.x_resolution == 0 && spec != nullptr) {
      out.info.x_resolution = spec->x_resolution;
      out.info.y_resolution = spec->y_resolution;
    }
  }
  out.decoder = PenDecoder(std::move(layouts), out.descriptor ? &*out.descriptor : nullptr);
  return out;
}

} // namespace penshape::drivers
