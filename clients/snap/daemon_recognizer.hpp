#pragma once
// Recognizing a page's strokes through penshaped's Geometry.Recognize RPC (several strokes per
// call, grouped by the daemon as the core's StrokeGrouper does, or not), in the daemon's units:
// the strokes are scaled so that the median of their clean pen radii is 1 mm and sent as samples
// of a tablet of 1000 units per mm, with that radius in the settings; the answers are scaled back.
// A page of more strokes than one call takes (64) goes in consecutive batches, each grouped on
// its own. The daemon certifies on the ink of one constant radius (pressure widths are not sent)
// with its own tolerance rule, so `snap` sends nothing here when a tolerance is given (it runs
// in-process).
#include <grpcpp/channel.h>

#include <memory>
#include <stdexcept>

#include "page_recognizer.hpp"

namespace penshape::snap {

// A failed call: the status message and whether the daemon went away (then the caller may fall
// back to the core in-process) or refused the stroke.
struct DaemonCallFailed : std::runtime_error {
  DaemonCallFailed(const std::string& what, bool unavailable_)
      : std::runtime_error(what), unavailable(unavailable_) {}
  bool unavailable;
};

// Throws DaemonCallFailed when a call fails.
PageRecognizer daemon_recognizer(const std::shared_ptr<grpc::Channel>& channel);

} // namespace penshape::snap
