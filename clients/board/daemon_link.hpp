#pragma once
// The board's connection to penshaped: one Live.StreamSamples call carrying the board's pen
// samples; the daemon's events come back on a reader thread and are handed to `on_event`.
// Pen settings travel in the stream's first message, so changing them restarts the stream
// (between strokes).
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <grpcpp/channel.h>

#include "penshape/v1/live.grpc.pb.h"

namespace penshape::board {

// The board as a tablet: device units are 1/16 pixel, and 4 pixels make a millimetre.
inline constexpr double kPixelsPerMm = 4.0;
inline constexpr int kUnitsPerPixel = 16;

class DaemonLink {
 public:
  using EventHandler = std::function<void(const v1::LiveEvent&)>;
  // Called once when the stream ends with an error (e.g. the daemon stopped).
  using ErrorHandler = std::function<void(const std::string&)>;

  DaemonLink(std::shared_ptr<grpc::Channel> channel, int width_px, int height_px,
             EventHandler on_event, ErrorHandler on_error);
  ~DaemonLink(); // ends the stream and waits for the daemon's last events

  // (Re)starts the stream with these settings; waits for the previous stream's events first.
  void start(double pen_radius_mm, double tolerance_fraction);
  // One sample at window pixel (x, y); `tip` false ends the stroke. Returns false when the stream
  // is broken.
  bool send(float x, float y, bool tip, std::int64_t time_us);

 private:
  void stop();
  std::unique_ptr<v1::Live::Stub> stub_;
  v1::TabletInfo tablet_;
  EventHandler on_event_;
  ErrorHandler on_error_;
  std::unique_ptr<grpc::ClientContext> context_;
  std::unique_ptr<grpc::ClientReaderWriter<v1::StreamSamplesRequest, v1::LiveEvent>> stream_;
  std::thread reader_;
  std::mutex write_mutex_;
};

} // namespace penshape::board
