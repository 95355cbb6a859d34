#pragma once
#include "penshape/v1/info.grpc.pb.h"

namespace penshape::daemon {

// penshape.v1.InfoService: what this daemon is and what it was built with.
class InfoServiceImpl final : public penshape::v1::InfoService::Service {
 public:
  grpc::Status GetVersion(grpc::ServerContext* context,
                          const penshape::v1::GetVersionRequest* request,
                          penshape::v1::GetVersionResponse* response) override;
};

} // namespace penshape::daemon
