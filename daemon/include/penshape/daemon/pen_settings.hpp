#pragma once
// Pen radius and tolerances, and the store that keeps them per device model.
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace penshape::daemon {

// When a live stroke snaps: at pen-up, when held still while down, or both (live.proto).
enum class SnapTrigger : std::uint8_t { kPenUp, kHold, kBoth };

// eps = tolerance_fraction * pen_radius_mm, delta = precision_fraction * eps.
struct PenSettings {
  double pen_radius_mm = 1.0;        // in [0.05, 50]
  double tolerance_fraction = 0.5;   // in [0.01, 4]
  double precision_fraction = 0.125; // in [1/1024, 1/2]
  // Hold to snap. Both by default: every stroke still snaps at pen-up, as it did before hold to
  // snap, and holding snaps at once.
  SnapTrigger snap_trigger = SnapTrigger::kBoth;
  double hold_ms = 500;        // in [100, 10000]
  double hold_radius_mm = 1.0; // in [0.01, 10]
  // Writing strokes are recognized too (off: writing is left as drawn; a hold is always drawing).
  bool snap_writing = false;
  friend bool operator==(const PenSettings&, const PenSettings&) = default;
};

// A partial update: the fields present are changed.
struct PenSettingsUpdate {
  std::optional<double> pen_radius_mm;
  std::optional<double> tolerance_fraction;
  std::optional<double> precision_fraction;
  std::optional<SnapTrigger> snap_trigger;
  std::optional<double> hold_ms;
  std::optional<double> hold_radius_mm;
  std::optional<bool> snap_writing;
};

// Thrown for a value out of range; the message names the field (prefixed by `field_prefix`).
struct SettingsError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Checks the ranges above; throws SettingsError naming e.g. "settings.pen_radius_mm".
void validate(const PenSettingsUpdate& update, const std::string& field_prefix);
PenSettings apply(PenSettings base, const PenSettingsUpdate& update);

// A device key is "" (the defaults) or "vvvv:pppp", four lowercase hex digits each.
bool is_valid_device_key(const std::string& key);
std::string device_key(unsigned vendor_id, unsigned product_id);

// "pen_up", "hold", "both"; parse_snap_trigger answers nothing for another word.
const char* snap_trigger_name(SnapTrigger trigger);
std::optional<SnapTrigger> parse_snap_trigger(const std::string& word);

// Thread-safe: read by the geometry workers, written by the Config service.
class SettingsStore {
 public:
  explicit SettingsStore(PenSettings defaults = {},
                         std::map<std::string, PenSettingsUpdate> per_device = {});

  [[nodiscard]] PenSettings effective(const std::string& key) const;
  [[nodiscard]] bool overridden(const std::string& key) const;
  // Applies a validated update to the defaults (key "") or to one device key.
  PenSettings update(const std::string& key, const PenSettingsUpdate& update, bool reset);
  [[nodiscard]] std::vector<std::string> overridden_keys() const;

 private:
  mutable std::mutex mutex_;
  PenSettings defaults_;
  // Per device, only the fields it sets; the rest follow the defaults.
  std::map<std::string, PenSettingsUpdate> per_device_;
};

} // namespace penshape::daemon
