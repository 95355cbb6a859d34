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

// Where a profile's physical size (resolution) came from.
enum class SizeSource : std::uint8_t {
  kUnknown,    // nothing said: x_resolution is 0, coordinates are NOT millimetres
  kTable,      // the tablet table's width_mm / height_mm
  kDescriptor, // the report descriptor's physical extents and unit
  kProbe,      // a vendor probe (UC-Logic string descriptor 200/100)
  kConfig,     // the user's configuration ([device "VID:PID"] width_mm, height_mm)
};
std::string_view size_source_name(SizeSource s);

struct DeviceProfile {
  TabletInfo info; // identity, maxima and resolution of the primary pen layout
  Protocol protocol = Protocol::kHid;
  std::string family = "hid";       // report family of the chosen table row (or probe)
  const TabletSpec* spec = nullptr; // the table row chosen, if any
  SizeSource size_source = SizeSource::kUnknown;
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

// Every string descriptor index to read at open for a device: its rows' protocols' indexes and
// the indexes their device_match needs; for a VID/PID in no row, the probing of a vendor known
// by VID (Huion/Gaomon 256c and UC-Logic 5543: string 200, then 100).
std::vector<std::uint8_t> vendor_string_indexes(std::uint16_t vendor_id, std::uint16_t product_id);

// Takes a physical size from the configuration when the profile has none (never overrides the
// table, the descriptor or a probe). Returns whether it was used.
bool apply_configured_size(DeviceProfile& profile, double width_mm, double height_mm);

} // namespace penshape::drivers
