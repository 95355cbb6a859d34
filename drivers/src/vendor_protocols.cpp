// The UC-Logic probe: parameters from string descriptor 200/100 and the layout they size.
#include "penshape/drivers/vendor_protocols.hpp"

#include <string>

#include "penshape/drivers/report_families.hpp"

namespace penshape::drivers {
namespace {

std::uint32_t le(std::span<const std::uint8_t> b, std::size_t at, std::size_t n) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < n; ++i) v |= static_cast<std::uint32_t>(b[at + i]) << (8 * i);
  return v;
}

} // namespace

UcLogicParams parse_uclogic_params(std::span<const std::uint8_t> s, int version) {
  if (version != 1 && version != 2) throw std::invalid_argument("UC-Logic params: bad version");
  // v1 (string 100): X le16 @2, Y le16 @4, pressure le16 @8, resolution le16 @10.
  // v2 (string 200): X le24 @2, Y le24 @5, pressure le16 @8, resolution le16 @10.
  if (s.size() < 12) {
    throw std::invalid_argument("UC-Logic params: string descriptor of " +
                                std::to_string(s.size()) + " bytes, need 12");
  }
  if (s[1] != 0x03) throw std::invalid_argument("UC-Logic params: not a string descriptor");
  if (s[0] < 12) throw std::invalid_argument("UC-Logic params: bLength below 12");
  UcLogicParams p;
  p.version = version;
  p.x_max = static_cast<std::int32_t>(version == 2 ? le(s, 2, 3) : le(s, 2, 2));
  p.y_max = static_cast<std::int32_t>(version == 2 ? le(s, 5, 3) : le(s, 4, 2));
  p.pressure_max = le(s, 8, 2);
  p.resolution_lpi = le(s, 10, 2);
  if (p.x_max <= 0 || p.y_max <= 0 || p.pressure_max == 0) {
    throw std::invalid_argument("UC-Logic params: zero maxima (tablet not in a known mode)");
  }
  return p;
}

PenLayout uclogic_pen_layout(const UcLogicParams& p) {
  // The "uclogic" family lists the v2 layout (report 8) first and the v1 layout (report 7)
  // second (data/families.tsv); the probe supplies maxima and resolution.
  TabletSpec spec;
  spec.x_max = p.x_max;
  spec.y_max = p.y_max;
  spec.pressure_max = p.pressure_max;
  spec.x_resolution = p.resolution_lpi / 25.4;
  spec.y_resolution = spec.x_resolution;
  const auto layouts = family_layouts(*find_family("uclogic"), spec);
  PenLayout l = layouts.at(p.version == 2 ? 0 : 1);
  l.origin = p.version == 2 ? "uclogic-v2" : "uclogic-v1";
  return l;
}

} // namespace penshape::drivers
