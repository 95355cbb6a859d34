#pragma once
// Sending a tablet's init reports (the vendor-mode switch) when it is opened. Kept apart from the
// hidraw backend so that what happens when a device refuses one is tested without a device.
#include <functional>
#include <string>
#include <vector>

#include "penshape/drivers/tablet_table.hpp"

namespace penshape::drivers {

// Sends the feature and output reports of `init` in order through `send` (hidapi's convention: a
// negative result is a refusal; string-descriptor steps are read elsewhere and skipped here). At
// the first refusal it logs a line naming `device` on stderr and stops: the tablet then stays in
// firmware mode, whose reports its descriptor's pens decode. Returns whether every report was
// accepted.
bool send_init_reports(const std::string& device, const std::vector<InitStep>& init,
                       const std::function<int(const InitStep&)>& send);

} // namespace penshape::drivers
