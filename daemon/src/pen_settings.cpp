#include "penshape/daemon/pen_settings.hpp"

#include <cmath>
#include <cstdio>

#include "penshape/types/lookup_table.hpp"

namespace penshape::daemon {
namespace {

void check_range(const std::optional<double>& value, double lo, double hi,
                 const std::string& field) {
  if (!value) return;
  const double v = *value;
  if (std::isnan(v)) throw SettingsError(field + " is NaN");
  if (!(v >= lo && v <= hi)) {
    char text[160];
    std::snprintf(text, sizeof text, " is %g, outside [%g, %g]", v, lo, hi);
    throw SettingsError(field + text);
  }
}

std::string join(const std::string& prefix, const char* name) {
  return prefix.empty() ? std::string(name) : prefix + "." + name;
}

} // namespace

void validate(const PenSettingsUpdate& update, const std::string& field_prefix) {
  check_range(update.pen_radius_mm, 0.05, 50.0, join(field_prefix, "pen_radius_mm"));
  check_range(update.tolerance_fraction, 0.01, 4.0, join(field_prefix, "tolerance_fraction"));
  check_range(update.precision_fraction, 1.0 / 1024.0, 0.5,
              join(field_prefix, "precision_fraction"));
  check_range(update.hold_ms, 100, 10000, join(field_prefix, "hold_ms"));
  check_range(update.hold_radius_mm, 0.01, 10, join(field_prefix, "hold_radius_mm"));
}

PenSettings apply(PenSettings base, const PenSettingsUpdate& update) {
  if (update.pen_radius_mm) base.pen_radius_mm = *update.pen_radius_mm;
  if (update.tolerance_fraction) base.tolerance_fraction = *update.tolerance_fraction;
  if (update.precision_fraction) base.precision_fraction = *update.precision_fraction;
  if (update.snap_trigger) base.snap_trigger = *update.snap_trigger;
  if (update.hold_ms) base.hold_ms = *update.hold_ms;
  if (update.hold_radius_mm) base.hold_radius_mm = *update.hold_radius_mm;
  if (update.snap_writing) base.snap_writing = *update.snap_writing;
  return base;
}

bool is_valid_device_key(const std::string& key) {
  if (key.empty()) return true;
  if (key.size() != 9 || key[4] != ':') return false;
  for (std::size_t i = 0; i < key.size(); ++i) {
    if (i == 4) continue;
    const char c = key[i];
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

std::string device_key(unsigned vendor_id, unsigned product_id) {
  char text[16];
  std::snprintf(text, sizeof text, "%04x:%04x", vendor_id & 0xffffU, product_id & 0xffffU);
  return text;
}

namespace {
// The config's words for the snap triggers, for both directions.
constexpr LookupTable<SnapTrigger, const char*, 3> kSnapTriggerNames{
    {{SnapTrigger::kPenUp, "pen_up"}, {SnapTrigger::kHold, "hold"}, {SnapTrigger::kBoth, "both"}}};
} // namespace

const char* snap_trigger_name(SnapTrigger trigger) {
  return lookup_or(kSnapTriggerNames, trigger, "both");
}

std::optional<SnapTrigger> parse_snap_trigger(const std::string& word) {
  return reverse_lookup(kSnapTriggerNames, word);
}

SettingsStore::SettingsStore(PenSettings defaults,
                             std::map<std::string, PenSettingsUpdate> per_device)
    : defaults_(defaults), per_device_(std::move(per_device)) {}

PenSettings SettingsStore::effective(const std::string& key) const {
  std::lock_guard lock(mutex_);
  const auto it = per_device_.find(key);
  return it == per_device_.end() ? defaults_ : apply(defaults_, it->second);
}

bool SettingsStore::overridden(const std::string& key) const {
  std::lock_guard lock(mutex_);
  return per_device_.count(key) != 0;
}

PenSettings SettingsStore::update(const std::string& key, const PenSettingsUpdate& update,
                                  bool reset) {
  std::lock_guard lock(mutex_);
  if (key.empty()) {
    defaults_ = apply(defaults_, update);
    return defaults_;
  }
  PenSettingsUpdate& own = per_device_[key];
  if (reset) own = {};
  if (update.pen_radius_mm) own.pen_radius_mm = update.pen_radius_mm;
  if (update.tolerance_fraction) own.tolerance_fraction = update.tolerance_fraction;
  if (update.precision_fraction) own.precision_fraction = update.precision_fraction;
  if (update.snap_trigger) own.snap_trigger = update.snap_trigger;
  if (update.hold_ms) own.hold_ms = update.hold_ms;
  if (update.hold_radius_mm) own.hold_radius_mm = update.hold_radius_mm;
  if (update.snap_writing) own.snap_writing = update.snap_writing;
  return apply(defaults_, own);
}

std::vector<std::string> SettingsStore::overridden_keys() const {
  std::lock_guard lock(mutex_);
  std::vector<std::string> keys;
  for (const auto& [key, value] : per_device_) keys.push_back(key);
  return keys;
}

} // namespace penshape::daemon
