// An app's own strokes are grouped like a tablet's live strokes, through the real daemon
// (penshaped's server with the recognizing analyzer) and a real gRPC client over a unix socket:
// four sides submitted with one group_key (SubmitStroke), or streamed (StreamSamples), come back
// as one rectangle whose answer names the four strokes and supersedes the earlier answers;
// grouping off gives four segments; keys and streams never group with each other; a key beyond
// max_group_keys forgets the least recently used one; an over-long key is refused, naming it.
// Checks are independent of the recognizer: the strokes drawn, the corners drawn, the ids seen.
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "drawn_rectangle.hpp"
#include "fakes.hpp"
#include "penshape/daemon/config.hpp"
#include "penshape/daemon/proto_convert.hpp"
#include "penshape/daemon/recognizing_analyzer.hpp"
#include "penshape/daemon/server.hpp"
#include "penshape/v1/live.grpc.pb.h"

namespace {

namespace v1 = penshape::v1;
using penshape::PointD;
using penshape::daemon_test::ids_of;
using penshape::daemon_test::is_rectangle;
using penshape::daemon_test::side;

// The four sides of the rectangle (20, 20)-(80, 60) mm, small gaps and overshoots at corners.
std::vector<std::vector<PointD>> rectangle_sides() {
  return penshape::daemon_test::rectangle_sides(20, 20, 80, 60);
}

// Samples of a stroke along `mm` on the test tablet (100 units per mm), 5 ms apart from
// `*clock_us` on (advanced), the last one tip up.
std::vector<v1::PenSample> samples_of(const std::vector<PointD>& mm, std::int64_t* clock_us) {
  std::vector<v1::PenSample> out;
  for (std::size_t i = 0; i <= mm.size(); ++i) {
    const PointD p = mm[std::min(i, mm.size() - 1)];
    v1::PenSample s;
    s.set_time_us(*clock_us += 5000);
    s.set_x(static_cast<std::int32_t>(std::lround(p.x * 100)));
    s.set_y(static_cast<std::int32_t>(std::lround(p.y * 100)));
    s.set_pressure(i < mm.size() ? 500 : 0);
    s.set_in_range(true);
    s.set_tip(i < mm.size());
    out.push_back(s);
  }
  return out;
}

struct Daemon {
  explicit Daemon(const std::string& config_text = "")
      : address("unix-abstract:penshape-app-grouping-" + std::to_string(::getpid()) + "-" +
                std::to_string(++count)),
        server(options(address, config_text),
               {nullptr, nullptr, penshape::daemon::make_recognizing_analyzer()}),
        live(v1::Live::NewStub(grpc::CreateChannel(address, grpc::InsecureChannelCredentials()))) {}
  static penshape::daemon::ServerOptions options(const std::string& address,
                                                 const std::string& config_text) {
    penshape::daemon::ServerOptions o;
    o.address = address;
    o.config = penshape::daemon::parse_config(config_text, "test.conf");
    return o;
  }
  // One stroke along `mm` submitted with `key`, 300 ms after the key's previous stroke.
  v1::SubmitStrokeResponse submit(const std::string& key, const std::vector<PointD>& mm,
                                  grpc::Status* status = nullptr) {
    v1::SubmitStrokeRequest request;
    request.set_group_key(key);
    penshape::daemon::to_proto(penshape::testing::test_tablet(),
                               request.mutable_stroke()->mutable_tablet());
    std::int64_t& clock = clock_us[key];
    clock += 300'000;
    for (const v1::PenSample& s : samples_of(mm, &clock))
      *request.mutable_stroke()->add_samples() = s;
    grpc::ClientContext ctx;
    v1::SubmitStrokeResponse response;
    const grpc::Status s = live->SubmitStroke(&ctx, request, &response);
    if (status != nullptr) *status = s;
    EXPECT_TRUE(status != nullptr || s.ok()) << s.error_message();
    return response;
  }
  static inline std::atomic<int> count{0};
  std::string address;
  penshape::daemon::PenshapeServer server;
  std::unique_ptr<v1::Live::Stub> live;
  std::map<std::string, std::int64_t> clock_us;
};

// The corners of the answer are the corners drawn (within the wobble and the corner gaps), and
// its certificate holds.
void expect_drawn_rectangle(const v1::Shape& shape) {
  ASSERT_TRUE(is_rectangle(shape.kind())) << shape.kind();
  ASSERT_EQ(shape.vertices().vertices_size(), 4);
  for (const PointD c : {PointD{20, 20}, PointD{80, 20}, PointD{80, 60}, PointD{20, 60}}) {
    double nearest = 1e9;
    for (const auto& v : shape.vertices().vertices()) {
      nearest = std::min(nearest, std::hypot(v.x() - c.x, v.y() - c.y));
    }
    EXPECT_LT(nearest, 1.5) << "corner " << c.x << "," << c.y;
  }
  EXPECT_LE(shape.certificate().hausdorff_bound().approx(),
            shape.certificate().tolerance().approx());
}

// Each earlier answer the last one supersedes is one of `earlier` (the first three strokes'
// answers), and together they cover exactly those three strokes.
template <typename Answer>
void expect_supersedes_the_first_three(const Answer& last, const std::vector<Answer>& earlier) {
  ASSERT_FALSE(last.supersedes_shape_ids().empty());
  std::set<std::uint64_t> covered;
  for (const std::uint64_t sid : last.supersedes_shape_ids()) {
    bool found = false;
    for (const Answer& e : earlier) {
      if (e.shape_id() != sid) continue;
      found = true;
      if (e.replaced_stroke_ids().empty()) covered.insert(e.stroke_id());
      covered.insert(e.replaced_stroke_ids().begin(), e.replaced_stroke_ids().end());
    }
    EXPECT_TRUE(found) << "supersedes an answer given before: " << sid;
  }
  std::set<std::uint64_t> first_three;
  for (const Answer& e : earlier) first_three.insert(e.stroke_id());
  EXPECT_EQ(covered, first_three);
}

TEST(AppGrouping, FourSidesSubmittedWithOneKeyAreOneRectangle) {
  Daemon d;
  std::vector<v1::SubmitStrokeResponse> answers;
  for (const auto& s : rectangle_sides()) answers.push_back(d.submit("page-1", s));
  ASSERT_EQ(answers.size(), 4U);
  std::set<std::uint64_t> shape_ids;
  for (const auto& a : answers) {
    EXPECT_NE(a.shape_id(), 0U);
    EXPECT_TRUE(shape_ids.insert(a.shape_id()).second) << "shape ids are unique";
  }
  const v1::SubmitStrokeResponse last = answers.back();
  expect_drawn_rectangle(last.shape());
  EXPECT_EQ(ids_of(last.replaced_stroke_ids()),
            (std::vector<std::uint64_t>{answers[0].stroke_id(), answers[1].stroke_id(),
                                        answers[2].stroke_id(), answers[3].stroke_id()}));
  answers.pop_back();
  expect_supersedes_the_first_three(last, answers);
}

TEST(AppGrouping, GroupingOffGivesFourSegments) {
  Daemon d("grouping = false\n");
  for (const auto& s : rectangle_sides()) {
    const v1::SubmitStrokeResponse a = d.submit("page-1", s);
    EXPECT_EQ(a.shape().kind(), v1::SHAPE_KIND_SEGMENT);
    EXPECT_EQ(ids_of(a.replaced_stroke_ids()), std::vector<std::uint64_t>{a.stroke_id()});
    EXPECT_TRUE(a.supersedes_shape_ids().empty());
  }
}

TEST(AppGrouping, WithoutAKeyEachStrokeStandsAlone) {
  Daemon d;
  for (const auto& s : rectangle_sides()) {
    const v1::SubmitStrokeResponse a = d.submit("", s);
    EXPECT_EQ(a.shape().kind(), v1::SHAPE_KIND_SEGMENT);
    EXPECT_EQ(ids_of(a.replaced_stroke_ids()), std::vector<std::uint64_t>{a.stroke_id()});
  }
}

TEST(AppGrouping, KeysNeverGroupTogetherAndTheLeastRecentlyUsedIsForgotten) {
  {
    Daemon d;
    const auto sides = rectangle_sides();
    for (std::size_t i = 0; i < sides.size(); ++i) {
      const v1::SubmitStrokeResponse a = d.submit(i % 2 == 0 ? "a" : "b", sides[i]);
      EXPECT_FALSE(is_rectangle(a.shape().kind())) << "side " << i;
      EXPECT_LE(a.replaced_stroke_ids_size(), 1) << "side " << i; // opposite sides never join
    }
  }
  {
    // One key kept: a stroke of another key in between forgets the first key's strokes.
    Daemon d("max_group_keys = 1\n");
    const auto sides = rectangle_sides();
    for (std::size_t i = 0; i < 3; ++i) d.submit("a", sides[i]);
    d.submit("b", side({150, 120}, {170, 120}));
    const v1::SubmitStrokeResponse last = d.submit("a", sides[3]);
    EXPECT_FALSE(is_rectangle(last.shape().kind()));
    EXPECT_TRUE(last.supersedes_shape_ids().empty());
  }
}

TEST(AppGrouping, AnOverLongKeyIsRefusedNamingIt) {
  Daemon d;
  grpc::Status status;
  d.submit(std::string(129, 'k'), rectangle_sides()[0], &status);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(status.error_message().find("group_key"), std::string::npos) << status.error_message();
  d.submit(std::string(128, 'k'), rectangle_sides()[0], &status);
  EXPECT_TRUE(status.ok()) << status.error_message();
}

// The ShapeRecognized events of one StreamSamples stream that draws `strokes`.
std::vector<v1::ShapeRecognized> stream_strokes(Daemon& d,
                                                const std::vector<std::vector<PointD>>& strokes) {
  grpc::ClientContext ctx;
  auto stream = d.live->StreamSamples(&ctx);
  v1::StreamSamplesRequest start;
  penshape::daemon::to_proto(penshape::testing::test_tablet(),
                             start.mutable_start()->mutable_tablet());
  EXPECT_TRUE(stream->Write(start));
  std::int64_t clock = 0;
  for (const auto& mm : strokes) {
    clock += 300'000;
    v1::StreamSamplesRequest batch;
    for (const v1::PenSample& s : samples_of(mm, &clock)) {
      *batch.mutable_samples()->add_samples() = s;
    }
    EXPECT_TRUE(stream->Write(batch));
  }
  stream->WritesDone();
  std::vector<v1::ShapeRecognized> shapes;
  v1::LiveEvent event;
  while (stream->Read(&event)) {
    if (event.has_shape()) shapes.push_back(event.shape());
  }
  const grpc::Status status = stream->Finish();
  EXPECT_TRUE(status.ok()) << status.error_message();
  return shapes;
}

TEST(AppGrouping, FourSidesStreamedAreOneRectangle) {
  Daemon d;
  std::vector<v1::ShapeRecognized> shapes = stream_strokes(d, rectangle_sides());
  ASSERT_EQ(shapes.size(), 4U);
  const v1::ShapeRecognized last = shapes.back();
  expect_drawn_rectangle(last.shape());
  EXPECT_EQ(ids_of(last.replaced_stroke_ids()),
            (std::vector<std::uint64_t>{shapes[0].stroke_id(), shapes[1].stroke_id(),
                                        shapes[2].stroke_id(), shapes[3].stroke_id()}));
  EXPECT_EQ(last.supersedes_sequences_size(), last.supersedes_shape_ids_size());
  shapes.pop_back();
  expect_supersedes_the_first_three(last, shapes);
}

TEST(AppGrouping, TwoStreamsNeverGroupTogether) {
  Daemon d;
  const auto sides = rectangle_sides();
  const auto first = stream_strokes(d, {sides[0], sides[1]});
  const auto second = stream_strokes(d, {sides[2], sides[3]});
  ASSERT_EQ(second.size(), 2U);
  for (const auto& s : second) {
    EXPECT_FALSE(is_rectangle(s.shape().kind()));
    for (const std::uint64_t id : s.replaced_stroke_ids()) {
      for (const auto& f : first) EXPECT_NE(id, f.stroke_id());
    }
  }
}

} // namespace
