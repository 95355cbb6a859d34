#include "info_service.hpp"

#include <grpcpp/grpcpp.h>

#include "penshape/core/version.hpp"
#include "penshape/drivers/hid_enumeration.hpp"

namespace penshape::daemon {

grpc::Status InfoServiceImpl::GetVersion(grpc::ServerContext* /*context*/,
                                         const penshape::v1::GetVersionRequest* /*request*/,
                                         penshape::v1::GetVersionResponse* response) {
  response->set_version(penshape::version());
  for (const auto& v : penshape::geometry_library_versions()) response->add_components(v);
  for (const auto& v : penshape::drivers::device_library_versions()) response->add_components(v);
  response->add_components("gRPC " + grpc::Version());
  return grpc::Status::OK;
}

} // namespace penshape::daemon
