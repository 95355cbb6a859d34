// Raw HID reports through the daemon: only subscribers that ask get them (in the hub and over
// gRPC), they are every report of the device byte for byte (the real PenPartner capture of the
// shared corpus, skipped without it, and the generated recording in its protocol with status
// reports added, replayed through the drivers' device manager, reports that decode to no sample
// included), DeviceInfo
// carries the device's descriptor and ids, a slow raw subscriber loses only its oldest events
// (counted), and the raw-subscriber limit answers RESOURCE_EXHAUSTED.
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "penshape/daemon/config.hpp"
#include "penshape/daemon/device_manager_source.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/daemon/shape_hub.hpp"
#include "penshape/drivers/recording.hpp"
#include "penshape/drivers/replay.hpp"
#include "penshape/v1/live.grpc.pb.h"
#include "test_data.hpp"

namespace penshape::testing {
namespace {

namespace v1 = penshape::v1;
using namespace std::chrono_literals;

// The generated recording in the PenPartner's protocol (Wacom Graphire, 056a:0061), with a
// status report (ID 0x63, as the real device sends; no pen sample) after every 10th report.
drivers::Recording generated_capture() {
  drivers::Recording r = drivers::load_recording_file(std::string(PENSHAPE_SOURCE_DIR) +
                                                      "/recordings/generated-graphire.hidrec");
  std::vector<drivers::HidEvent> events;
  for (std::size_t i = 0; i < r.events.size(); ++i) {
    events.push_back(r.events[i]);
    if (i % 10 == 9) events.push_back({r.events[i].time_us + 1, {0x63, 0, 0, 0, 0, 0, 0, 0}});
  }
  r.events = std::move(events);
  return r;
}

v1::LiveEvent raw_event(const std::string& device, std::int64_t time_us) {
  v1::LiveEvent e;
  e.set_device_id(device);
  e.mutable_raw_report()->set_data(std::string("\x02\x90\x01", 3));
  e.mutable_raw_report()->set_time_us(time_us);
  return e;
}

v1::LiveEvent sample_event(const std::string& device) {
  v1::LiveEvent e;
  e.set_device_id(device);
  e.mutable_samples()->add_samples()->set_x(7);
  return e;
}

std::string unique_address(const std::string& tag) {
  static int counter = 0;
  return "unix-abstract:penshape-raw-" + tag + "-" + std::to_string(::getpid()) + "-" +
         std::to_string(++counter);
}

bool wait_for_subscribers(daemon::PenshapeServer& server, std::size_t n) {
  const auto until = std::chrono::steady_clock::now() + 30s;
  while (server.hub().subscriber_count() < n && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(1ms);
  }
  return server.hub().subscriber_count() == n;
}

// --- the hub ------------------------------------------------------------------------------------

TEST(RawReportsHub, OnlySubscribersThatAskGetThem) {
  daemon::ShapeHub hub(16, 4);
  daemon::EventFilter plain;
  plain.samples = true;
  auto without = hub.subscribe(plain, 16);
  EXPECT_FALSE(hub.wants_raw_reports()); // nobody asked: producers build no raw events
  daemon::EventFilter raw;
  raw.strokes = false;
  raw.raw_reports = true;
  auto with = hub.subscribe(raw, 16);
  ASSERT_NE(with, nullptr);
  EXPECT_TRUE(hub.wants_raw_reports());

  hub.publish(raw_event("pen", 1));
  hub.publish(sample_event("pen"));
  hub.publish(raw_event("pen", 2));

  auto d = without->next(0ms);
  ASSERT_NE(d.event, nullptr);
  EXPECT_TRUE(d.event->has_samples());
  EXPECT_EQ(without->next(0ms).event, nullptr); // no raw report reached it
  for (std::int64_t t : {1, 2}) {
    auto r = with->next(0ms);
    ASSERT_NE(r.event, nullptr);
    ASSERT_TRUE(r.event->has_raw_report());
    EXPECT_EQ(r.event->raw_report().time_us(), t);
  }
  EXPECT_EQ(with->next(0ms).event, nullptr); // and no sample reached the raw-only one

  with.reset();
  EXPECT_FALSE(hub.wants_raw_reports()); // the last raw subscriber left
}

TEST(RawReportsHub, RawSubscribersAreLimitedOthersAreNot) {
  daemon::ShapeHub hub(8, 1);
  daemon::EventFilter raw;
  raw.raw_reports = true;
  auto first = hub.subscribe(raw, 4);
  ASSERT_NE(first, nullptr);
  daemon::ShapeHub::Refusal why = daemon::ShapeHub::Refusal::kNone;
  EXPECT_EQ(hub.subscribe(raw, 4, &why), nullptr);
  EXPECT_EQ(why, daemon::ShapeHub::Refusal::kRawFull);
  EXPECT_NE(hub.subscribe(daemon::EventFilter{}, 4, &why), nullptr);
  EXPECT_EQ(why, daemon::ShapeHub::Refusal::kNone);
  first.reset();
  EXPECT_NE(hub.subscribe(raw, 4), nullptr); // its slot is free again
}

TEST(RawReportsHub, RawSubscribersAlsoSeeTheirDevicesComeAndGo) {
  daemon::ShapeHub hub(8, 1);
  daemon::EventFilter raw;
  raw.strokes = false;
  raw.raw_reports = true;
  raw.device_ids = {"pen"};
  auto sub = hub.subscribe(raw, 8);
  v1::LiveEvent attached;
  attached.set_device_id("pen");
  attached.mutable_device_attached()->mutable_device()->set_id("pen");
  v1::LiveEvent other = attached;
  other.set_device_id("other");
  v1::LiveEvent detached;
  detached.set_device_id("pen");
  detached.mutable_device_detached()->set_device_id("pen");
  hub.publish(other);
  hub.publish(attached);
  hub.publish(raw_event("other", 5));
  hub.publish(raw_event("pen", 6));
  hub.publish(detached);
  EXPECT_TRUE(sub->next(0ms).event->has_device_attached());
  EXPECT_EQ(sub->next(0ms).event->raw_report().time_us(), 6);
  EXPECT_TRUE(sub->next(0ms).event->has_device_detached());
  EXPECT_EQ(sub->next(0ms).event, nullptr);
}

TEST(RawReportsHub, SlowRawSubscriberLosesOnlyItsOldestReports) {
  daemon::ShapeHub hub(8, 2);
  daemon::EventFilter raw;
  raw.raw_reports = true;
  auto slow = hub.subscribe(raw, 4);
  auto fast = hub.subscribe(raw, 64);
  for (std::int64_t t = 0; t < 10; ++t) hub.publish(raw_event("pen", t));
  // The newest four, in order; the six oldest counted as lost with the first delivery.
  for (std::int64_t t = 6; t < 10; ++t) {
    const auto d = slow->next(0ms);
    ASSERT_NE(d.event, nullptr);
    EXPECT_EQ(d.event->raw_report().time_us(), t);
    EXPECT_EQ(d.dropped, t == 6 ? 6U : 0U);
    EXPECT_EQ(d.dropped_total, 6U);
  }
  for (std::int64_t t = 0; t < 10; ++t) { // the other raw subscriber lost nothing
    const auto d = fast->next(0ms);
    ASSERT_NE(d.event, nullptr);
    EXPECT_EQ(d.event->raw_report().time_us(), t);
    EXPECT_EQ(d.dropped, 0U);
  }
}

TEST(RawReportsHub, TheLimitIsAConfigKeyAndZeroTurnsRawReportsOff) {
  EXPECT_EQ(daemon::parse_config("", "empty.conf").limits.max_raw_report_subscribers, 8U);
  const auto config = daemon::parse_config("max_raw_report_subscribers = 0\n", "test.conf");
  EXPECT_EQ(config.limits.max_raw_report_subscribers, 0U);
  EXPECT_ANY_THROW(daemon::parse_config("max_raw_report_subscribers = 5000\n", "test.conf"));
  daemon::ShapeHub hub(8, config.limits.max_raw_report_subscribers);
  daemon::EventFilter raw;
  raw.raw_reports = true;
  daemon::ShapeHub::Refusal why = daemon::ShapeHub::Refusal::kNone;
  EXPECT_EQ(hub.subscribe(raw, 4, &why), nullptr);
  EXPECT_EQ(why, daemon::ShapeHub::Refusal::kRawFull);
  EXPECT_FALSE(hub.wants_raw_reports());
}

// --- over gRPC ----------------------------------------------------------------------------------

// The real PenPartner capture replayed through the drivers' device manager (the path of a live
// tablet): the raw subscriber gets the device's descriptor and ids and every report of the file,
// byte for byte with its time; the subscriber without include_raw_reports gets none of them.
void expect_every_report_only_for_subscribers_that_ask(const drivers::Recording& recording,
                                                       const std::string& name,
                                                       const std::string& phys) {
  ASSERT_GT(recording.events.size(), 500U);
  const drivers::ReplayResult offline =
      drivers::replay(recording, drivers::ReplaySpeed::kAsFastAsPossible);
  // The capture holds reports that decode to no pen sample (report ID 0x63): they must come too.
  ASSERT_LT(offline.counters.pen_samples, recording.events.size());

  daemon::ServerOptions options;
  options.address = unique_address("replay");
  options.config.limits.subscriber_queue_events = 1U << 16; // completeness here, not slowness
  auto source = std::make_shared<daemon::DeviceManagerSource>(nullptr);
  daemon::PenshapeServer server(options, {source, nullptr, nullptr});
  auto live =
      v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));

  grpc::ClientContext raw_ctx;
  raw_ctx.set_deadline(std::chrono::system_clock::now() + 120s);
  v1::SubscribeRequest raw_request;
  raw_request.set_include_raw_reports(true);
  auto raw_reader = live->Subscribe(&raw_ctx, raw_request);
  grpc::ClientContext plain_ctx;
  plain_ctx.set_deadline(std::chrono::system_clock::now() + 120s);
  v1::SubscribeRequest plain_request;
  plain_request.set_include_samples(true);
  plain_request.set_include_previews(true);
  auto plain_reader = live->Subscribe(&plain_ctx, plain_request);
  ASSERT_TRUE(wait_for_subscribers(server, 2));

  source->replay(recording, drivers::ReplaySpeed::kAsFastAsPossible);

  std::vector<v1::LiveEvent> raw_events;
  v1::LiveEvent event;
  while (raw_reader->Read(&event)) {
    raw_events.push_back(event);
    if (event.has_device_detached()) break;
  }
  raw_ctx.TryCancel();
  (void)raw_reader->Finish();

  ASSERT_GE(raw_events.size(), 2U);
  ASSERT_TRUE(raw_events.front().has_device_attached());
  const v1::DeviceInfo& device = raw_events.front().device_attached().device();
  ASSERT_TRUE(device.has_hid());
  EXPECT_EQ(device.hid().report_descriptor(),
            std::string(recording.descriptor.begin(), recording.descriptor.end()));
  EXPECT_EQ(device.hid().name(), name);
  EXPECT_EQ(device.hid().phys(), phys);
  EXPECT_EQ(device.hid().bus(), 3U);
  EXPECT_EQ(device.hid().vendor_id(), 0x056aU);
  EXPECT_EQ(device.hid().product_id(), 0x0061U);
  ASSERT_TRUE(raw_events.back().has_device_detached());
  std::vector<drivers::HidEvent> got;
  for (std::size_t i = 1; i + 1 < raw_events.size(); ++i) {
    const v1::LiveEvent& e = raw_events[i];
    EXPECT_EQ(e.device_id(), device.id());
    if (!e.has_raw_report()) { // the strokes come too (a Subscribe default), never samples
      EXPECT_TRUE(e.has_stroke_started() || e.has_stroke_finished()) << e.ShortDebugString();
      continue;
    }
    const std::string& data = e.raw_report().data();
    got.push_back({e.raw_report().time_us(), std::vector<std::uint8_t>(data.begin(), data.end())});
  }
  ASSERT_EQ(got.size(), recording.events.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_EQ(got[i], recording.events[i]) << "report " << i;
  }

  // The plain subscriber: every decoded sample, and not one raw report.
  server.shutdown(); // its stream ends once everything published was delivered
  std::size_t samples = 0;
  std::size_t raw_reports = 0;
  while (plain_reader->Read(&event)) {
    if (event.has_samples()) samples += static_cast<std::size_t>(event.samples().samples_size());
    if (event.has_raw_report()) ++raw_reports;
  }
  EXPECT_TRUE(plain_reader->Finish().ok());
  EXPECT_EQ(raw_reports, 0U);
  EXPECT_EQ(samples, offline.samples.size());
}

TEST(RawReportsGrpc, EveryReportOfTheDeviceOnlyForSubscribersThatAsk) {
  PENSHAPE_SHARED_OR_SKIP(capture, "hid/wacom-hid-descriptors/Wacom_PenPartner/hidrecord.txt");
  expect_every_report_only_for_subscribers_that_ask(drivers::load_recording_file(capture),
                                                    "WACOM FT-0203-UV1.4-2",
                                                    "usb-0000:00:1d.0-1.8/input0");
}

TEST(RawReportsGrpc, EveryReportOfAGeneratedDeviceOnlyForSubscribersThatAsk) {
  expect_every_report_only_for_subscribers_that_ask(generated_capture(),
                                                    "penshape generated pen (vendor-graphire)",
                                                    "usb-penshape-generated/input0");
}

// A source whose reader sends raw reports only while the sink wants them, as the device manager
// source does; its device carries HID facts.
class RawSource final : public daemon::SampleSource {
 public:
  void start(daemon::SampleSink& sink) override { sink_ = &sink; }
  void stop() override {}
  [[nodiscard]] std::vector<daemon::DeviceDescriptor> devices() const override { return {}; }
  void attach() {
    daemon::DeviceDescriptor d;
    d.id = "pen";
    d.tablet.x_max = 1000;
    d.tablet.y_max = 1000;
    d.hid.report_descriptor = {0x05, 0x0d, 0x09, 0x02, 0xa1, 0x01, 0xc0};
    d.hid.name = "Raw Test Pen";
    d.hid.bus = Bus::kUsb;
    d.hid.vendor_id = 0x28bd;
    d.hid.product_id = 0x0905;
    d.hid.vendor_strings[200] = {0x06, 0x03, 0x41, 0x00, 0x42, 0x00};
    sink_->device_attached(d);
  }
  // `count` reports of 64 bytes, time_us = index; returns how many the sink took.
  std::size_t emit(std::size_t count) {
    std::size_t sent = 0;
    std::vector<std::uint8_t> report(64, 0);
    for (std::size_t i = 0; i < count; ++i) {
      report[0] = 0x02;
      report[1] = static_cast<std::uint8_t>(i);
      if (!sink_->wants_raw_reports()) continue;
      sink_->raw_report("pen", report, static_cast<std::int64_t>(i));
      ++sent;
    }
    return sent;
  }

 private:
  daemon::SampleSink* sink_ = nullptr;
};

TEST(RawReportsGrpc, ListDevicesCarriesTheHidFacts) {
  daemon::ServerOptions options;
  options.address = unique_address("list");
  auto source = std::make_shared<RawSource>();
  daemon::PenshapeServer server(options, {source, nullptr, nullptr});
  source->attach();
  auto live =
      v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  v1::ListDevicesResponse devices;
  ASSERT_TRUE(live->ListDevices(&ctx, {}, &devices).ok());
  ASSERT_EQ(devices.devices_size(), 1);
  const v1::HidFacts& hid = devices.devices(0).hid();
  EXPECT_EQ(hid.report_descriptor(), std::string("\x05\x0d\x09\x02\xa1\x01\xc0", 7));
  EXPECT_EQ(hid.name(), "Raw Test Pen");
  EXPECT_EQ(hid.bus(), 3U);
  EXPECT_EQ(hid.vendor_id(), 0x28bdU);
  EXPECT_EQ(hid.product_id(), 0x0905U);
  ASSERT_EQ(hid.vendor_strings_size(), 1);
  EXPECT_EQ(hid.vendor_strings(0).index(), 200U);
  EXPECT_EQ(hid.vendor_strings(0).data(), std::string("\x06\x03\x41\x00\x42\x00", 6));
}

TEST(RawReportsGrpc, NobodyAskingMeansNoRawReportIsMade) {
  daemon::ServerOptions options;
  options.address = unique_address("nobody");
  auto source = std::make_shared<RawSource>();
  daemon::PenshapeServer server(options, {source, nullptr, nullptr});
  source->attach();
  auto live =
      v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  v1::SubscribeRequest request;
  request.set_include_samples(true);
  auto reader = live->Subscribe(&ctx, request);
  ASSERT_TRUE(wait_for_subscribers(server, 1));
  const std::uint64_t published = server.hub().published();
  EXPECT_EQ(source->emit(100), 0U);
  EXPECT_EQ(server.hub().published(), published);
  ctx.TryCancel();
  (void)reader->Finish();
}

// A raw subscriber that does not read while 40,000 reports (2.5 MB, far beyond what the transport
// buffers) are published: it loses its oldest queued reports, is told how many, and still gets the
// newest ones in order; a subscriber reading samples meanwhile is not held up.
TEST(RawReportsGrpc, SlowRawSubscriberLosesOnlyItsOldestEvents) {
  constexpr std::size_t kQueue = 16;
  constexpr std::size_t kReports = 40'000;
  daemon::ServerOptions options;
  options.address = unique_address("slow");
  auto source = std::make_shared<RawSource>();
  daemon::PenshapeServer server(options, {source, nullptr, nullptr});
  source->attach();
  auto live =
      v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  grpc::ClientContext ctx;
  ctx.set_deadline(std::chrono::system_clock::now() + 120s);
  v1::SubscribeRequest request;
  request.set_include_raw_reports(true);
  request.set_max_queued_events(kQueue);
  auto reader = live->Subscribe(&ctx, request);
  ASSERT_TRUE(wait_for_subscribers(server, 1));

  ASSERT_EQ(source->emit(kReports), kReports);

  std::vector<std::int64_t> times;
  std::uint64_t dropped = 0;
  std::uint64_t dropped_total = 0;
  v1::LiveEvent event;
  while (times.size() + dropped < kReports && reader->Read(&event)) {
    if (event.has_dropped()) {
      dropped += event.dropped().count();
      dropped_total = event.dropped().total();
    } else if (event.has_raw_report()) {
      times.push_back(event.raw_report().time_us());
    }
  }
  ctx.TryCancel();
  (void)reader->Finish();
  EXPECT_GT(dropped, 0U);
  EXPECT_EQ(dropped_total, dropped);
  EXPECT_EQ(times.size() + dropped, kReports); // every report delivered or counted
  for (std::size_t i = 1; i < times.size(); ++i) ASSERT_LT(times[i - 1], times[i]) << i;
  // Only old ones were lost: the newest kQueue reports all arrived, in order, at the end.
  ASSERT_GE(times.size(), kQueue);
  for (std::size_t k = 0; k < kQueue; ++k) {
    EXPECT_EQ(times[times.size() - kQueue + k], static_cast<std::int64_t>(kReports - kQueue + k));
  }
}

TEST(RawReportsGrpc, TooManyRawSubscribersIsResourceExhausted) {
  daemon::ServerOptions options;
  options.address = unique_address("limit");
  options.config.limits.max_raw_report_subscribers = 1;
  daemon::PenshapeServer server(options);
  auto live =
      v1::Live::NewStub(grpc::CreateChannel(options.address, grpc::InsecureChannelCredentials()));
  grpc::ClientContext first_ctx;
  v1::SubscribeRequest raw;
  raw.set_include_raw_reports(true);
  auto first = live->Subscribe(&first_ctx, raw);
  ASSERT_TRUE(wait_for_subscribers(server, 1));
  {
    grpc::ClientContext ctx;
    auto second = live->Subscribe(&ctx, raw);
    v1::LiveEvent event;
    EXPECT_FALSE(second->Read(&event));
    const grpc::Status status = second->Finish();
    EXPECT_EQ(status.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
    EXPECT_NE(status.error_message().find("max_raw_report_subscribers = 1"), std::string::npos)
        << status.error_message();
  }
  { // without raw reports there is room
    grpc::ClientContext ctx;
    auto plain = live->Subscribe(&ctx, v1::SubscribeRequest{});
    ASSERT_TRUE(wait_for_subscribers(server, 2));
    ctx.TryCancel();
    (void)plain->Finish();
  }
  first_ctx.TryCancel();
  (void)first->Finish();
}

} // namespace
} // namespace penshape::testing
