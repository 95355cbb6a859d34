#pragma once
// `penshape replay` through penshaped: each stroke the local decode finds is submitted to the
// daemon (Live.SubmitStroke), which answers with the shape it certifies for that stroke.
#include <memory>
#include <optional>
#include <string>

#include "penshape/types/stroke.hpp"
#include "penshape/v1/live.grpc.pb.h"

namespace penshape::cli {

class ReplayDaemon {
 public:
  // Connected to penshaped at `address`, or nullopt (with the reason in `why`) when it does not
  // answer.
  static std::optional<ReplayDaemon> connect(const std::string& address, std::string& why);

  // The daemon's shape for the stroke drawn on `tablet`; throws std::runtime_error naming the
  // call when the daemon refuses it or goes away.
  v1::Shape recognize(const Stroke& stroke, const TabletInfo& tablet);

 private:
  ReplayDaemon(std::unique_ptr<v1::Live::Stub> stub, std::string address)
      : stub_(std::move(stub)), address_(std::move(address)) {}
  std::unique_ptr<v1::Live::Stub> stub_;
  std::string address_;
};

} // namespace penshape::cli
