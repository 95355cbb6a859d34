// A tablet's init reports, sent in order; a refusal is logged and ends the sequence (see
// init_reports.hpp).
#include "init_reports.hpp"

#include <cstdio>

namespace penshape::drivers {

bool send_init_reports(const std::string& device, const std::vector<InitStep>& init,
                       const std::function<int(const InitStep&)>& send) {
  for (const InitStep& step : init) {
    if (step.kind == InitStep::Kind::kStringDescriptor) continue;
    if (send(step) < 0) {
      // A tablet that refuses its vendor-mode switch still sends its firmware-mode reports,
      // which the descriptor's pens decode: say so and carry on rather than drop the device.
      std::fprintf(stderr,
                   "penshape drivers: %s refused an init report (%zu bytes); staying in firmware "
                   "mode\n",
                   device.c_str(), step.bytes.size());
      return false;
    }
  }
  return true;
}

} // namespace penshape::drivers
