// libFuzzer: arbitrary text as hid-recorder, usbhid-dump and tablet-table input. Must parse or
// throw the documented error; a parsed hid-recorder file must survive a write/read round trip
// unchanged.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/tablet_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace penshape::drivers;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const Recording r = read_hid_recorder(text);
    if (read_hid_recorder(write_hid_recorder(r)) != r) std::abort();
  } catch (const RecordingError&) {
  }
  try {
    (void)read_usbhid_dump(text);
  } catch (const RecordingError&) {
  }
  try {
    (void)parse_tablet_table(text);
  } catch (const TabletTableError&) {
  }
  (void)detect_format(text);
  return 0;
}
