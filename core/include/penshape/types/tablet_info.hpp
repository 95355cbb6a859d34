#pragma once
// What penshape knows of a tablet: identity, coordinate ranges and physical resolution.
#include <cstdint>
#include <string>

namespace penshape {

enum class Bus : std::uint16_t { kUnknown = 0, kUsb = 0x03, kBluetooth = 0x05, kI2c = 0x18 };

struct TabletInfo {
  Bus bus = Bus::kUnknown;
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::string name;
  std::int32_t x_max = 0;         // logical maximum of X, device units
  std::int32_t y_max = 0;         // logical maximum of Y, device units
  std::uint32_t pressure_max = 0; // 0 when the pen reports no pressure
  double x_resolution = 0.0;      // device units per millimetre (0 = unknown)
  double y_resolution = 0.0;      // device units per millimetre (0 = unknown)
  bool has_tilt = false;

  // Width and height of the active area in millimetres; 0 when the resolution is unknown.
  [[nodiscard]] double width_mm() const {
    return x_resolution > 0 ? static_cast<double>(x_max) / x_resolution : 0.0;
  }
  [[nodiscard]] double height_mm() const {
    return y_resolution > 0 ? static_cast<double>(y_max) / y_resolution : 0.0;
  }

  friend bool operator==(const TabletInfo&, const TabletInfo&) = default;
};

} // namespace penshape
