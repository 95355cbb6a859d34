// DeviceInfo says whether a tablet's physical size is known and where it came from: a tablet
// that gives none is reported with physical_size_known false (and resolution 0), unless the
// config file's [device."vvvv:pppp"] width_mm/height_mm gives one.
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "penshape/daemon/device_manager_source.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/v1/live.grpc.pb.h"

namespace penshape::testing {
namespace {

namespace v1 = penshape::v1;
using namespace std::chrono_literals;

// A pen (report 2: tip, 16-bit X/Y of 0..32767) without physical extents or unit.
const std::vector<std::uint8_t> kNoUnits = {
    0x05, 0x0D, 0x09, 0x02, 0xA1, 0x01, 0x85, 0x02, 0x09, 0x20, 0xA1, 0x00, 0x09, 0x42, 0x15, 0x00,
    0x25, 0x01, 0x75, 0x01, 0x95, 0x01, 0x81, 0x02, 0x75, 0x07, 0x81, 0x03, 0x05, 0x01, 0x09, 0x30,
    0x26, 0xFF, 0x7F, 0x75, 0x10, 0x95, 0x01, 0x81, 0x02, 0x09, 0x31, 0x81, 0x02, 0xC0, 0xC0};

// A device that stays attached for a minute (its second report is due then).
drivers::Recording unsized_tablet(std::uint16_t product_id) {
  drivers::Recording rec;
  rec.identity = {Bus::kUsb, 0x1234, product_id, "unsized"};
  rec.has_identity = true;
  rec.descriptor = kNoUnits;
  rec.events.push_back({0, {0x02, 0x00, 0x10, 0x00, 0x20, 0x00}});
  rec.events.push_back({60'000'000, {0x02, 0x00, 0x10, 0x00, 0x20, 0x00}});
  return rec;
}

TEST(DeviceInfoSize, UnknownUnlessConfigured) {
  daemon::ServerOptions options;
  options.address = "unix-abstract:penshape-size-" + std::to_string(::getpid());
  auto source = std::make_shared<daemon::DeviceManagerSource>(
      nullptr, daemon::DeviceManagerSource::DeviceSizes{{"1234:0001", {160.0, 100.0}}});
  daemon::PenshapeServer server(options, {source, nullptr, nullptr});
  source->replay(unsized_tablet(0x0001), drivers::ReplaySpeed::kOriginal);
  source->replay(unsized_tablet(0x0002), drivers::ReplaySpeed::kOriginal);
  auto live =
      v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  v1::ListDevicesResponse devices;
  for (int i = 0; i < 200 && devices.devices_size() < 2; ++i) {
    grpc::ClientContext ctx;
    ASSERT_TRUE(live->ListDevices(&ctx, {}, &devices).ok());
    if (devices.devices_size() < 2) std::this_thread::sleep_for(20ms);
  }
  ASSERT_EQ(devices.devices_size(), 2);
  for (const auto& d : devices.devices()) {
    if (d.tablet().product_id() == 1) {
      EXPECT_TRUE(d.physical_size_known());
      EXPECT_EQ(d.size_source(), "config");
      EXPECT_DOUBLE_EQ(d.tablet().x_resolution(), 32767 / 160.0);
    } else {
      EXPECT_FALSE(d.physical_size_known());
      EXPECT_EQ(d.size_source(), "unknown");
      EXPECT_EQ(d.tablet().x_resolution(), 0.0);
    }
    EXPECT_EQ(d.family(), "hid");
  }
  source->stop();
}

} // namespace
} // namespace penshape::testing
