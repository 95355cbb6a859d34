#pragma once
// Test helpers: the HID data of the shared corpus (hid/, absent from a bare clone), the project's
// generated descriptors and recordings, and the descriptor collections.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "test_data.hpp"

namespace penshape::drivers::testing {

// The shared corpus's hid/ folder; nullopt in a bare clone.
inline std::optional<std::filesystem::path> hid_dir() { return test::shared_path("hid"); }

// The real Wacom PenPartner hid-recorder capture, in the shared corpus.
inline constexpr const char* kPenPartnerCapture =
    "hid/wacom-hid-descriptors/Wacom_PenPartner/hidrecord.txt";

// A generated recording in the PenPartner's protocol (Wacom Graphire, 056a:0061, the drivers'
// table: 3250 x 2320, ~125 Hz): three strokes, made by recordings/generate.sh.
inline std::filesystem::path penpartner_capture() {
  return test::recordings_dir() / "generated-graphire.hidrec";
}

struct NamedDescriptor {
  std::string source; // path relative to hid/ (and the line for multi-descriptor files)
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::vector<std::uint8_t> bytes;
};

// Every descriptor under hid_dir(): the .hid.bin files of wacom-hid-descriptors and each R: line
// of the hid-tools and udev-hid-bpf collections; none without the shared corpus.
std::vector<NamedDescriptor> all_shared_descriptors();
// The pen descriptors the project writes (tests/support/gen/descriptor_gen.hpp), as
// "generated/<name>" with VID:PID 1209:7e50.
std::vector<NamedDescriptor> generated_descriptors();

} // namespace penshape::drivers::testing
