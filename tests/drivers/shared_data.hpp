#pragma once
// Test helpers: the HID data (the shared corpus's hid/ when present, else the descriptors bundled
// in tests/data/hid), the bundled PenPartner capture, and the descriptor collections.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "test_data.hpp"

namespace penshape::drivers::testing {

inline std::filesystem::path hid_dir() { return test::collection_dir("hid"); }

// The real Wacom PenPartner hid-recorder capture, bundled in recordings/ (ODbL).
inline std::filesystem::path penpartner_capture() {
  return test::recordings_dir() / "wacom-penpartner.hidrec";
}

struct NamedDescriptor {
  std::string source; // path relative to hid/ (and the line for multi-descriptor files)
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::vector<std::uint8_t> bytes;
};

// Every descriptor under hid_dir(): the .hid.bin files of wacom-hid-descriptors and each R: line
// of the hid-tools and udev-hid-bpf collections (absent from the bundled subset).
std::vector<NamedDescriptor> all_shared_descriptors();

} // namespace penshape::drivers::testing
