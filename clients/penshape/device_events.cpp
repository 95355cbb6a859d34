#include "device_events.hpp"

namespace penshape::cli {

DeviceEvents::DeviceEvents(v1::Live::Stub& stub, std::function<void(const v1::LiveEvent&)> on_event)
    : reader_(stub.WatchDevices(&context_, v1::WatchDevicesRequest())) {
  thread_ = std::thread([this, on_event = std::move(on_event)] {
    v1::LiveEvent event;
    while (reader_->Read(&event)) on_event(event);
  });
}

DeviceEvents::~DeviceEvents() {
  context_.TryCancel();
  if (thread_.joinable()) thread_.join();
  (void)reader_->Finish(); // CANCELLED, or how the daemon ended it: the main stream reports that
}

} // namespace penshape::cli
