#pragma once
// The data-driven tablet table: one row per supported tablet (VID/PID -> protocol, maxima,
// resolution, name). The rows live in drivers/data/tablets.tsv (compiled in); adding a tablet is
// a new row, not new code. Facts come from the OpenTabletDriver and libwacom data.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace penshape::drivers {

// How a tablet's pen reports are obtained (one parser per protocol).
enum class Protocol : std::uint8_t {
  kHid,           // the report descriptor describes the pen
  kWacomHid,      // descriptor pens after Wacom's mode-switch feature report (02 02)
  kWacomGraphire, // Wacom Graphire/PenPartner/PenStation report 2 (vendor page descriptor)
  kWacomBamboo,   // Wacom Bamboo / One by Wacom pen report 2, after the mode switch (02 02)
  kWacomIntuos,   // Wacom Intuos 2-5 / Intuos Pro pen report 2, after the mode switch (02 02)
  kUcLogic,       // Huion/Gaomon: vendor mode via USB string descriptor 200 (or 100)
  kXpPen,         // XP-Pen/Ugee: vendor mode via output report 02 B0 02|04 when needed
};

std::string_view protocol_name(Protocol p);
std::optional<Protocol> protocol_from_name(std::string_view name);

// One step of a vendor initialisation.
struct InitStep {
  enum class Kind : std::uint8_t { kFeatureReport, kOutputReport, kStringDescriptor };
  Kind kind = Kind::kFeatureReport;
  std::vector<std::uint8_t> bytes; // report bytes, report ID first (reports)
  std::uint8_t string_index = 0;   // kStringDescriptor
  friend bool operator==(const InitStep&, const InitStep&) = default;
};

struct TabletSpec {
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  Protocol protocol = Protocol::kHid;
  std::vector<InitStep> init;
  std::int32_t x_max = 0; // 0: unknown or model-dependent
  std::int32_t y_max = 0;
  std::uint32_t pressure_max = 0;
  double x_resolution = 0.0; // units per mm
  double y_resolution = 0.0;
  std::string name;
};

// Thrown by parse_tablet_table with the 1-based line number in the message.
struct TabletTableError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses the TSV format of drivers/data/tablets.tsv ('#' comments; columns: vid pid protocol init
// x_max y_max pressure_max x_res y_res name; init is '-' or space-separated F:hex, O:hex, S:index).
std::vector<TabletSpec> parse_tablet_table(std::string_view tsv);

// The built-in table (parsed once).
const std::vector<TabletSpec>& builtin_tablets();

// The built-in row for a VID/PID, if any.
const TabletSpec* find_tablet(std::uint16_t vendor_id, std::uint16_t product_id);

} // namespace penshape::drivers
