#pragma once
// One decoded pen report, in device units. Drivers produce these; core consumes them.
#include <cstdint>

namespace penshape {

// Bit flags of PenSample::buttons.
enum PenButton : std::uint32_t {
  kBarrel1 = 1U << 0,
  kBarrel2 = 1U << 1,
  kBarrel3 = 1U << 2,
  kEraser = 1U << 3, // eraser end in use (HID Eraser or Invert)
};

struct PenSample {
  std::int64_t time_us = 0;   // microseconds since the stream's epoch (monotonic)
  std::int32_t x = 0;         // device units, 0..TabletInfo::x_max
  std::int32_t y = 0;         // device units, 0..TabletInfo::y_max (y grows downwards)
  std::uint32_t pressure = 0; // 0..TabletInfo::pressure_max
  std::int16_t tilt_x = 0;    // degrees, positive to the right; 0 when not reported
  std::int16_t tilt_y = 0;    // degrees, positive towards the user; 0 when not reported
  std::uint32_t buttons = 0;  // PenButton flags
  bool in_range = false;      // the pen is within detection range (proximity)
  bool tip = false;           // the tip touches the surface

  friend bool operator==(const PenSample&, const PenSample&) = default;
};

} // namespace penshape
