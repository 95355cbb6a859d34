#include "penshape/daemon/server.hpp"

#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <condition_variable>
#include <mutex>

#include "penshape/v1/info.grpc.pb.h"

namespace {

std::string unique_abstract_address() {
  return "unix-abstract:penshape-test-" + std::to_string(::getpid());
}

TEST(Server, AnswersVersionAndHealth) {
  const std::string address = unique_abstract_address();
  penshape::daemon::PenshapeServer server({address, {}});
  auto channel = grpc::CreateChannel(address, grpc::InsecureChannelCredentials());

  auto info = penshape::v1::InfoService::NewStub(channel);
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
  penshape::v1::GetVersionResponse response;
  const grpc::Status status = info->GetVersion(&ctx, {}, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_FALSE(response.version().empty());
  bool has_cgal = false;
  bool has_grpc = false;
  for (const auto& c : response.components()) {
    has_cgal |= c.rfind("CGAL", 0) == 0;
    has_grpc |= c.rfind("gRPC", 0) == 0;
  }
  EXPECT_TRUE(has_cgal);
  EXPECT_TRUE(has_grpc);

  // The standard health service, through the generic stub (no grpc.health.v1 codegen needed).
  grpc::GenericStub generic(channel);
  grpc::ClientContext hctx;
  hctx.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
  // An empty HealthCheckRequest (service ""): the server's overall health.
  grpc::Slice empty_message("");
  grpc::ByteBuffer request(&empty_message, 1);
  grpc::ByteBuffer reply;
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  grpc::Status hstatus;
  generic.UnaryCall(&hctx, "/grpc.health.v1.Health/Check", {}, &request, &reply,
                    [&](grpc::Status s) {
                      std::lock_guard lock(m);
                      hstatus = std::move(s);
                      done = true;
                      cv.notify_one();
                    });
  std::unique_lock lock(m);
  cv.wait(lock, [&] { return done; });
  ASSERT_TRUE(hstatus.ok()) << hstatus.error_message();
  std::vector<grpc::Slice> slices;
  ASSERT_TRUE(reply.Dump(&slices).ok());
  std::string bytes;
  for (const auto& s : slices) bytes.append(reinterpret_cast<const char*>(s.begin()), s.size());
  // HealthCheckResponse{status: SERVING(1)} encodes as field 1, varint 1.
  EXPECT_EQ(bytes, std::string("\x08\x01", 2));
}

TEST(Server, RefusesAnUnbindableAddress) {
  EXPECT_THROW(penshape::daemon::PenshapeServer({"unix:/nonexistent-dir/x/penshape.sock", {}}),
               std::runtime_error);
}

} // namespace
