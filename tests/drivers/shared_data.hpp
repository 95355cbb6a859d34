#pragma once
// Test helpers: where the shared real data lives, and the descriptor collections in it.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace penshape::drivers::testing {

inline std::filesystem::path shared_data_dir() {
  if (const char* env = std::getenv("PENSHAPE_SHARED_DATA_DIR"); env != nullptr && *env) {
    return env;
  }
  return PENSHAPE_SHARED_DATA_DIR;
}

inline std::filesystem::path hid_dir() { return shared_data_dir() / "hid"; }

struct NamedDescriptor {
  std::string source; // path relative to hid/ (and the line for multi-descriptor files)
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::vector<std::uint8_t> bytes;
};

// Every descriptor in ../shared/data/hid: the .hid.bin files of wacom-hid-descriptors and each
// R: line of the hid-tools and udev-hid-bpf collections.
std::vector<NamedDescriptor> all_shared_descriptors();

} // namespace penshape::drivers::testing
