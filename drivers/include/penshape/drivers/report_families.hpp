#pragma once
// Report families: each vendor pen-report format as data (drivers/data/families.tsv, compiled
// in), so a tablet row names its family instead of needing code. A family is the protocol that
// opens the device plus the pen layouts (offsets and bits) its reports use; the tablet row adds
// maxima and physical size.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "penshape/drivers/pen_layout.hpp"
#include "penshape/drivers/tablet_table.hpp"

namespace penshape::drivers {

struct ReportFamily {
  std::string name;
  Protocol protocol = Protocol::kHid;
  // Pen layouts in the order the decoder tries them; maxima are 0 until family_layouts fills
  // them from a tablet row. Empty: the report descriptor describes the pen.
  std::vector<PenLayout> layouts;
};

// Thrown by parse_report_families with the 1-based line number and the bad token.
struct FamilyTableError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses the format of drivers/data/families.tsv (documented at its top).
std::vector<ReportFamily> parse_report_families(std::string_view tsv);

// The built-in families (parsed once).
const std::vector<ReportFamily>& builtin_families();

// The built-in family of that name, or nullptr.
const ReportFamily* find_family(std::string_view name);

// The family's layouts with X, Y and pressure maxima and resolution from `spec` (the tablet row,
// or maxima a vendor probe returned). Empty when the family has none or `spec` has no maxima.
std::vector<PenLayout> family_layouts(const ReportFamily& family, const TabletSpec& spec);

} // namespace penshape::drivers
