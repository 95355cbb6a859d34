// libFuzzer: arbitrary report streams through the decoders and the pipeline of real tablets
// (a generic HID pen, UC-Logic vendor mode, Wacom Graphire). Never crashes; every delivered
// sample lies within the tablet's maxima; strokes start with tip down and end with tip up.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "penshape/drivers/pen_pipeline.hpp"

namespace {

using namespace penshape;
using namespace penshape::drivers;

// HS610 firmware-mode pen interface (DIGImend rd/original1.txt, report 0x0A).
const std::vector<std::uint8_t> kHs610 = {
    0x05, 0x0D, 0x09, 0x02, 0xA1, 0x01, 0x85, 0x0A, 0x09, 0x20, 0xA1, 0x00, 0x09, 0x42, 0x09, 0x44,
    0x09, 0x45, 0x09, 0x3C, 0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x06, 0x81, 0x02, 0x09, 0x32,
    0x75, 0x01, 0x95, 0x01, 0x81, 0x02, 0x81, 0x03, 0x05, 0x01, 0x09, 0x30, 0x09, 0x31, 0x55, 0x0D,
    0x65, 0x33, 0x26, 0xFF, 0x7F, 0x35, 0x00, 0x46, 0x00, 0x08, 0x75, 0x10, 0x95, 0x02, 0x81, 0x02,
    0x05, 0x0D, 0x09, 0x30, 0x26, 0xFF, 0x1F, 0x75, 0x10, 0x95, 0x01, 0x81, 0x02, 0x09, 0x3D, 0x09,
    0x3E, 0x15, 0x81, 0x25, 0x7F, 0x75, 0x08, 0x95, 0x02, 0x81, 0x02, 0xC0, 0xC0};
const std::vector<std::uint8_t> kS200 = {0x13, 0x03, 0x70, 0xC6, 0x00, 0x06, 0x7C,
                                         0x00, 0xFF, 0x1F, 0xD8, 0x13, 0x03};

const std::vector<DeviceProfile>& profiles() {
  static const std::vector<DeviceProfile> p = {
      build_profile({Bus::kUsb, 0x256c, 0x0064, "hs610 firmware"}, kHs610),
      build_profile({Bus::kUsb, 0x256c, 0x006d, "hs610 vendor"}, kHs610, {{200, kS200}}),
      build_profile({Bus::kUsb, 0x056a, 0x0061, "penpartner"}, {}),
      // Vendor report families with no descriptor: any-ID (Veikk), two match bytes, 24-bit
      // coordinates (Intuos V2), a shifted copy (Wacom driver's Intuos), three-piece pressure.
      build_profile({Bus::kUsb, 0x2feb, 0x0006, "veikk a15 pro"}, {}),
      build_profile({Bus::kUsb, 0x056a, 0x0357, "intuos v2"}, {}),
      build_profile({Bus::kUsb, 0x056a, 0x0317, "intuos pro"}, {}),
  };
  return p;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const DeviceProfile& profile = profiles()[data[0] % profiles().size()];
  bool ok = true;
  PenPipeline pipeline(
      profile, {},
      {.on_sample =
           [&](const PenSample& s) {
             ok = ok && s.x >= 0 && s.x <= profile.info.x_max && s.y >= 0 &&
                  s.y <= profile.info.y_max && s.pressure <= profile.info.pressure_max;
           },
       .on_stroke =
           [&](Stroke&& st) {
             ok = ok && !st.samples.empty() && st.samples.front().tip && !st.samples.back().tip;
           }});
  // The rest is a stream: [length byte][report bytes]…, time advancing 4 ms per report.
  std::size_t pos = 1;
  std::int64_t t = 0;
  while (pos < size) {
    const std::size_t len = std::min<std::size_t>(data[pos] % 24, size - pos - 1);
    pipeline.on_report(std::span<const std::uint8_t>(data + pos + 1, len), t += 4000);
    if ((data[pos] & 0x80) != 0) pipeline.on_idle(t + 20000);
    pos += 1 + len;
  }
  pipeline.on_end();
  if (!ok) std::abort();
  return 0;
}
