#pragma once
// Everything needed to decode one device: chosen from its identity (tablet table row), its
// report descriptor, and vendor strings it returned. Shared by the live device manager, replay
// and the CLI so all three decode the same way.
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "penshape/drivers/hid_descriptor.hpp"
#include "penshape/drivers/pen_decoder.hpp"
#include "penshape/drivers/tablet_table.hpp"
#include "penshape/types/tablet_info.hpp"

namespace penshape::drivers {

struct DeviceIdentity {
  Bus bus = Bus::kUnknown;
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::string name;
};

// Raw USB string descriptors a vendor protocol read (index -> bLength, 0x03, payload).
using VendorStrings = std::map<std::uint8_t, std::vector<std::uint8_t>>;

struct DeviceProfile {
  TabletInfo info; // identity, maxima and resolution of the primary pen layout
  Protocol protocol = Protocol::kHid;
  std::optional<ParsedDescriptor> descriptor; // absent when none was given
  PenDecoder decoder{{}};
  std::vector<InitStep> init;     // reports to send when opening the device
  std::vector<std::string> notes; // why this layout was chosen (for `hid describe` and logs)

  [[nodiscard]] bool has_pen() const { return decoder.has_pen(); }
};

// Chooses layouts: the descriptor's pens, or the protocol's vendor layout when the descriptor
// does not describe the vendor report (a kernel driver such as hid-uclogic that already rewrote
// descriptor and reports wins). Throws DescriptorError for a malformed descriptor and
// std::invalid_argument for unusable vendor strings.
DeviceProfile build_profile(const DeviceIdentity& id, std::span<const std::uint8_t> descriptor,
                            const VendorStrings& vendor_strings = {});

// String descriptor indexes a protocol reads at open (UC-Logic: 200, then 100 as fallback).
std::vector<std::uint8_t> vendor_string_indexes(Protocol p);

} // namespace penshape::drivers
