// The drawing board without its window: strokes, undo, scripts, and the StreamSamples link to a
// daemon the test serves (so sanitizers check this code with leak detection on).
#include <gtest/gtest.h>
#include <unistd.h>

#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>

#include "board_model.hpp"
#include "board_script.hpp"
#include "daemon_link.hpp"
#include "test_daemon.hpp"

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>

namespace penshape::board {
namespace {

v1::Shape square_shape() {
  v1::Shape s;
  s.set_kind(v1::SHAPE_KIND_SQUARE);
  for (auto [x, y] : {std::pair{1.0, 1.0}, {2.0, 1.0}, {2.0, 2.0}, {1.0, 2.0}}) {
    auto* p = s.mutable_vertices()->add_vertices();
    p->set_x(x);
    p->set_y(y);
  }
  return s;
}

TEST(BoardModel, DaemonIdsFollowTheDrawingOrderAndUndoUnsnapsThenRemoves) {
  BoardModel m;
  m.begin_stroke({1, 1}, 4);
  m.extend_stroke({2, 2});
  EXPECT_TRUE(m.drawing());
  m.end_stroke({3, 3});
  m.begin_stroke({10, 10}, 4);
  m.end_stroke({11, 11});
  ASSERT_EQ(m.strokes().size(), 2U);
  EXPECT_EQ(m.strokes()[0].points.size(), 3U);
  EXPECT_EQ(m.undo(), "nothing"); // the daemon has not answered the last stroke yet
  m.server_stroke_started(7);
  m.server_stroke_started(8);
  EXPECT_EQ(m.server_shape(7, square_shape()), 0);
  v1::Shape none;
  none.set_kind(v1::SHAPE_KIND_NONE);
  EXPECT_EQ(m.server_shape(8, none), 1);
  EXPECT_EQ(m.server_shape(9, square_shape()), -1); // unknown stroke
  EXPECT_TRUE(m.all_answered());
  EXPECT_TRUE(m.strokes()[0].snapped);
  EXPECT_FALSE(m.strokes()[1].snapped);
  EXPECT_EQ(m.strokes()[1].note, "no shape");
  EXPECT_EQ(m.undo(), "removed"); // the last stroke had no shape
  EXPECT_EQ(m.undo(), "unsnapped");
  ASSERT_EQ(m.strokes().size(), 1U);
  EXPECT_FALSE(m.strokes()[0].snapped);
  EXPECT_TRUE(m.strokes()[0].shape.has_value()); // kept: the raw stroke is shown instead
  EXPECT_EQ(m.undo(), "removed");
  EXPECT_EQ(m.undo(), "nothing");
}

TEST(BoardModel, NotAnalysedStrokesStayRaw) {
  BoardModel m;
  m.begin_stroke({1, 1}, 4);
  m.end_stroke({5, 5});
  m.server_stroke_started(3);
  EXPECT_EQ(m.server_not_analysed(3, "no recognizer"), 0);
  EXPECT_EQ(m.strokes()[0].note, "not analysed: no recognizer");
  EXPECT_FALSE(m.strokes()[0].snapped);
  m.clear();
  EXPECT_TRUE(m.strokes().empty());
}

TEST(BoardModel, FinishedStrokesWithoutAShapeSettleAfterTheStreamIsDrained) {
  BoardModel m;
  m.begin_stroke({1, 1}, 4);
  m.end_stroke({5, 5});
  m.begin_stroke({6, 6}, 4);
  m.end_stroke({9, 9});
  m.server_stroke_started(1);
  m.server_stroke_started(2);
  EXPECT_EQ(m.server_finished(1), 0);
  EXPECT_FALSE(m.all_finished_or_answered());
  EXPECT_EQ(m.server_finished(2), 1);
  EXPECT_EQ(m.server_shape(2, square_shape()), 1); // the shape follows its StrokeFinished
  EXPECT_TRUE(m.all_finished_or_answered());
  EXPECT_FALSE(m.all_answered());
  EXPECT_EQ(m.settle_finished(), 1); // stroke 1 got no shape
  EXPECT_TRUE(m.all_answered());
  EXPECT_EQ(m.strokes()[0].note, "the daemon sent no shape (no recognizer)");
  EXPECT_FALSE(m.strokes()[0].snapped);
  EXPECT_TRUE(m.strokes()[1].snapped);
  EXPECT_EQ(m.settle_finished(), 0);
}

TEST(BoardModel, PreviewsGuideTheStrokeBeingDrawnUntilItsAnswer) {
  BoardModel m;
  m.begin_stroke({1, 1}, 6);
  m.extend_stroke({5, 5});
  m.server_stroke_started(3);
  const v1::Shape guess = square_shape();
  EXPECT_EQ(m.server_preview(3, &guess), 0);
  ASSERT_TRUE(m.strokes()[0].preview.has_value());
  EXPECT_EQ(m.strokes()[0].preview->kind(), v1::SHAPE_KIND_SQUARE);
  EXPECT_EQ(m.server_preview(3, nullptr), 0); // nothing fits any more
  EXPECT_FALSE(m.strokes()[0].preview.has_value());
  EXPECT_EQ(m.server_preview(3, &guess), 0);
  m.end_stroke({9, 9});
  EXPECT_EQ(m.server_finished(3), 0);
  EXPECT_FALSE(m.strokes()[0].preview.has_value()); // the answer replaces the guide
  EXPECT_EQ(m.server_preview(3, &guess), -1);       // a late preview changes nothing
  EXPECT_FALSE(m.strokes()[0].preview.has_value());
  EXPECT_EQ(m.server_preview(99, &guess), -1); // unknown stroke
}

std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("penshape-board-core-" + std::to_string(::getpid()) + "-" + name);
  std::ofstream(path) << text;
  return path.string();
}

TEST(BoardScript, ParsesCommandsAndNamesTheBadLine) {
  const auto ok =
      read_script(write_file("ok.txt",
                             "# a square\ndown 10 20\nmove 30 20  # right\nup 30 20\nkey u\n"
                             "wait-answers 5\nscreenshot out.bmp\nquit\n"));
  ASSERT_EQ(ok.size(), 7U);
  EXPECT_EQ(ok[0].op, ScriptCommand::Op::kDown);
  EXPECT_EQ(ok[1].x, 30);
  EXPECT_EQ(ok[1].y, 20);
  EXPECT_EQ(ok[3].text, "u");
  EXPECT_EQ(ok[4].seconds, 5);
  EXPECT_EQ(ok[5].text, "out.bmp");
  EXPECT_EQ(ok[6].op, ScriptCommand::Op::kQuit);
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {"down 1\n", ":1: down needs two pixel coordinates"},
           {"move -1 2\n", ":1: move needs two pixel coordinates"},
           {"\nkey\n", ":2: key needs a key name"},
           {"wait-answers -3\n", ":1: wait-answers needs seconds"},
           {"up 1 2 3\n", ":1: unexpected '3'"},
           {"jump 1 2\n", ":1: unknown command 'jump'"}}) {
    try {
      (void)read_script(write_file("bad.txt", text));
      ADD_FAILURE() << text;
    } catch (const ScriptError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW((void)read_script("/nonexistent-dir/script.txt"), ScriptError);
}

TEST(DaemonLink, StreamsTheBoardsStrokesWithItsSettings) {
  testing::TestDaemon daemon("board-link");
  auto channel = grpc::CreateChannel(daemon.address, grpc::InsecureChannelCredentials());
  std::mutex m;
  std::vector<v1::LiveEvent> events;
  std::vector<std::string> errors;
  {
    DaemonLink link(
        channel, 800, 600,
        [&](const v1::LiveEvent& e) {
          std::lock_guard lock(m);
          events.push_back(e);
        },
        [&](const std::string& error) {
          std::lock_guard lock(m);
          errors.push_back(error);
        });
    link.start(1.5, 0.4);
    std::int64_t t = 0;
    for (auto [x, y] : {std::pair{100.f, 100.f}, {300.f, 100.f}, {300.f, 300.f}, {100.f, 300.f}}) {
      EXPECT_TRUE(link.send(x, y, true, t += 1000));
    }
    EXPECT_TRUE(link.send(100.5f, 100.25f, false, t += 1000));
  } // the destructor ends the stream after the daemon's answers
  EXPECT_TRUE(errors.empty());
  ASSERT_EQ(events.size(), 3U);
  EXPECT_TRUE(events[0].has_stroke_started());
  ASSERT_TRUE(events[1].has_stroke_finished());
  const auto& stroke = events[1].stroke_finished().stroke();
  ASSERT_EQ(stroke.samples_size(), 5);
  // 16 device units per pixel, 4 pixels per mm.
  EXPECT_EQ(stroke.samples(1).x(), 300 * kUnitsPerPixel);
  EXPECT_EQ(stroke.samples(4).x(), 1608);
  EXPECT_EQ(stroke.samples(4).y(), 1604);
  EXPECT_FALSE(stroke.samples(4).tip());
  EXPECT_DOUBLE_EQ(stroke.tablet().x_resolution(), kUnitsPerPixel * kPixelsPerMm);
  EXPECT_EQ(stroke.tablet().x_max(), 800 * kUnitsPerPixel);
  ASSERT_TRUE(events[2].has_shape());
  EXPECT_EQ(events[2].shape().shape().kind(), v1::SHAPE_KIND_SQUARE);
  EXPECT_DOUBLE_EQ(daemon.analyzer->last_settings.pen_radius_mm, 1.5);
  EXPECT_DOUBLE_EQ(daemon.analyzer->last_settings.tolerance_fraction, 0.4);
}

TEST(DaemonLink, ReportsADaemonThatGoesAway) {
  auto daemon = std::make_unique<testing::TestDaemon>("board-gone", false);
  auto channel = grpc::CreateChannel(daemon->address, grpc::InsecureChannelCredentials());
  std::vector<v1::LiveEvent> events;
  std::mutex m;
  std::condition_variable changed;
  DaemonLink link(
      channel, 400, 300,
      [&](const v1::LiveEvent& e) {
        std::lock_guard lock(m);
        events.push_back(e);
        changed.notify_all();
      },
      [](const std::string&) {});
  link.start(1, 0.5);
  EXPECT_TRUE(link.send(10, 10, true, 1000));
  EXPECT_TRUE(link.send(20, 10, false, 2000));
  {
    // The stroke is answered (not analysed: this daemon has no analyzer).
    std::unique_lock lock(m);
    ASSERT_TRUE(
        changed.wait_for(lock, std::chrono::seconds(30), [&] { return events.size() >= 2; }));
  }
  daemon.reset(); // the daemon stops and ends the call
  // Writing to a closed stream fails instead of blocking or crashing.
  bool failed = false;
  for (int i = 0; i < 100 && !failed; ++i) {
    failed = !link.send(30, 10, true, 3000 + i);
    if (!failed) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_TRUE(failed);
  std::lock_guard lock(m);
  EXPECT_TRUE(events[0].has_stroke_started());
  EXPECT_TRUE(events[1].has_stroke_finished());
  EXPECT_NE(events[1].stroke_finished().not_analysed(), "");
}

} // namespace
} // namespace penshape::board
