#include "config_service.hpp"

#include "call_runner.hpp"
#include "penshape/core/deconstruct.hpp"
#include "penshape/daemon/grouping_settings.hpp"
#include "penshape/daemon/proto_convert.hpp"

namespace penshape::daemon {
namespace {

grpc::Status check_key(const std::string& key) {
  if (is_valid_device_key(key)) return grpc::Status::OK;
  return {grpc::StatusCode::INVALID_ARGUMENT,
          "device_key is '" + key.substr(0, 64) +
              "'; expected \"\" (defaults) or \"vvvv:pppp\" (four lowercase hex digits each)"};
}

} // namespace

void ConfigServiceImpl::fill(const std::string& key, v1::SettingsResponse* response) const {
  response->set_device_key(key);
  to_proto(state_.settings.effective(key), response->mutable_effective());
  response->set_overridden(!key.empty() && state_.settings.overridden(key));
  to_proto(state_.grouping.get(), response->mutable_grouping());
}

grpc::Status ConfigServiceImpl::GetSettings(grpc::ServerContext* /*context*/,
                                            const v1::GetSettingsRequest* request,
                                            v1::SettingsResponse* response) {
  if (grpc::Status s = check_key(request->device_key()); !s.ok()) return s;
  fill(request->device_key(), response);
  return grpc::Status::OK;
}

grpc::Status ConfigServiceImpl::SetSettings(grpc::ServerContext* /*context*/,
                                            const v1::SetSettingsRequest* request,
                                            v1::SettingsResponse* response) {
  if (grpc::Status s = check_key(request->device_key()); !s.ok()) return s;
  try {
    const PenSettingsUpdate update = settings_update_from_proto(request->settings(), "settings");
    if (request->has_grouping()) {
      if (!request->device_key().empty()) {
        throw InvalidInput(
            "grouping: the live grouping is daemon-wide; set it with device_key \"\"");
      }
      // Checked whole before anything changes: a bad value leaves both settings as they were.
      (void)apply_grouping(state_.grouping.get(), request->grouping(), "grouping.");
    }
    state_.settings.update(request->device_key(), update, request->reset());
    if (request->has_grouping()) state_.grouping.update(request->grouping());
  } catch (...) {
    return status_from_current_exception(nullptr);
  }
  fill(request->device_key(), response);
  return grpc::Status::OK;
}

grpc::Status ConfigServiceImpl::ListSettings(grpc::ServerContext* /*context*/,
                                             const v1::ListSettingsRequest* /*request*/,
                                             v1::ListSettingsResponse* response) {
  fill("", response->add_settings());
  for (const std::string& key : state_.settings.overridden_keys()) {
    fill(key, response->add_settings());
  }
  return grpc::Status::OK;
}

} // namespace penshape::daemon
