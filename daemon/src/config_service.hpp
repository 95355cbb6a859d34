#pragma once
#include "daemon_state.hpp"
#include "penshape/v1/config.grpc.pb.h"

namespace penshape::daemon {

// penshape.v1.Config on the SettingsStore.
class ConfigServiceImpl final : public StateService<v1::Config::Service> {
 public:
  using StateService::StateService;

  grpc::Status GetSettings(grpc::ServerContext* context, const v1::GetSettingsRequest* request,
                           v1::SettingsResponse* response) override;
  grpc::Status SetSettings(grpc::ServerContext* context, const v1::SetSettingsRequest* request,
                           v1::SettingsResponse* response) override;
  grpc::Status ListSettings(grpc::ServerContext* context, const v1::ListSettingsRequest* request,
                            v1::ListSettingsResponse* response) override;

 private:
  void fill(const std::string& key, v1::SettingsResponse* response) const;
};

} // namespace penshape::daemon
