#pragma once
// Live.WatchDevices on its own thread: Subscribe carries strokes but no attach/detach events, so
// `watch --devices` and `record` (which stops when its tablet is unplugged) read both streams.
#include <functional>
#include <memory>
#include <thread>

#include "penshape/v1/live.grpc.pb.h"

namespace penshape::cli {

class DeviceEvents {
 public:
  // Calls `on_event` (on the thread) for every DeviceAttached / DeviceDetached event, starting
  // with the devices attached now.
  DeviceEvents(v1::Live::Stub& stub, std::function<void(const v1::LiveEvent&)> on_event);
  ~DeviceEvents(); // cancels the stream and joins the thread
  DeviceEvents(const DeviceEvents&) = delete;
  DeviceEvents& operator=(const DeviceEvents&) = delete;

 private:
  grpc::ClientContext context_;
  std::unique_ptr<grpc::ClientReader<v1::LiveEvent>> reader_;
  std::thread thread_;
};

} // namespace penshape::cli
