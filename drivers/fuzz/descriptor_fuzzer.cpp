// libFuzzer: arbitrary bytes as a report descriptor. Must parse or throw DescriptorError; a
// parsed one must yield pen layouts whose fields lie inside their reports, and a decoder that
// survives its own reports.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "penshape/drivers/device_profile.hpp"
#include "penshape/drivers/hid_descriptor.hpp"
#include "penshape/drivers/pen_layout.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace penshape::drivers;
  const std::span<const std::uint8_t> bytes(data, size);
  try {
    const ParsedDescriptor d = parse_report_descriptor(bytes);
    const auto pens = find_pen_layouts(d);
    const PenDecoder decoder(pens, &d);
    // Decode a report of every declared length, filled with the input itself.
    std::vector<std::uint8_t> report;
    penshape::PenSample s;
    for (const auto& r : d.reports) {
      report.assign(r.size_bytes(), 0xA5);
      if (!report.empty() && d.uses_report_ids) report[0] = r.report_id;
      for (std::size_t i = 1; i < report.size() && i <= size; ++i) report[i] = data[i - 1];
      (void)decoder.decode(report, 0, s);
      if (report.size() > 1) {
        report.pop_back();
        (void)decoder.decode(report, 1, s);
      }
    }
    // And the same bytes through the profile builder for each vendor protocol's VID/PID.
    for (const auto& id : {DeviceIdentity{penshape::Bus::kUsb, 0x256c, 0x006d, ""},
                           DeviceIdentity{penshape::Bus::kUsb, 0x056a, 0x0061, ""},
                           DeviceIdentity{penshape::Bus::kUsb, 0x28bd, 0x0907, ""}}) {
      (void)build_profile(id, bytes, {{200, std::vector<std::uint8_t>(data, data + size)}});
    }
  } catch (const DescriptorError&) {
  } catch (const std::invalid_argument&) { // vendor strings that are not UC-Logic parameters
  }
  return 0;
}
