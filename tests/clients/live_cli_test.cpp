// The live subcommands (devices, watch, record) of the real `penshape` binary against a daemon
// the test starts (in-process server on a unix-abstract socket, scripted tablet), including the
// error paths: no daemon, bad arguments, unwritable files.
#include <gtest/gtest.h>
#include <signal.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "child_process.hpp"
#include "dollar_stroke.hpp"
#include "svg_xml.hpp"
#include "test_daemon.hpp"

namespace penshape::testing {
namespace {

const std::string kCli = PENSHAPE_CLI;

std::pair<int, std::string> cli(std::vector<std::string> args,
                                const std::map<std::string, std::string>& env = {}) {
  args.insert(args.begin(), kCli);
  return run_program(args, env);
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::filesystem::path temp_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("penshape-clients-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The $1 rectangle, 40 device units (0.2 mm) per pixel, placed inside the tablet.
std::vector<PenSample> rectangle_samples() {
  return samples_from_points(read_dollar_gesture(dollar_rectangle_path()), 40.0, 2000, 1000);
}

TEST(LiveCli, EverySubcommandHasHelp) {
  for (const std::string cmd : {"devices", "watch", "record"}) {
    const auto [code, out] = cli({cmd, "--help"});
    EXPECT_EQ(code, 0) << cmd;
    EXPECT_NE(out.find("usage: penshape " + cmd), std::string::npos) << out;
    EXPECT_NE(out.find("--socket PATH"), std::string::npos) << out;
    EXPECT_NE(out.find("--address ADDR"), std::string::npos) << out;
  }
}

TEST(LiveCli, SaysClearlyWhenTheDaemonIsNotRunning) {
  const std::string absent = unique_test_address("absent");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"devices"}, {"watch"}, {"record", "/dev/null"}}) {
    auto with_address = args;
    with_address.push_back("--address");
    with_address.push_back(absent);
    const auto [code, out] = cli(with_address);
    EXPECT_EQ(code, 1) << args[0] << ": " << out;
    EXPECT_NE(out.find("penshaped is not running at " + absent), std::string::npos) << out;
  }
  const auto [code, out] = cli({"devices", "--socket", "/nonexistent-dir/penshape.sock"});
  EXPECT_EQ(code, 1);
  EXPECT_NE(out.find("penshaped is not running at unix:/nonexistent-dir/penshape.sock"),
            std::string::npos)
      << out;
}

TEST(LiveCli, DefaultSocketIsInTheRuntimeDir) {
  const auto dir = temp_dir("runtime");
  const auto [code, out] = cli({"devices"}, {{"XDG_RUNTIME_DIR", dir.string()}});
  EXPECT_EQ(code, 1);
  EXPECT_NE(out.find("penshaped is not running at unix:" + dir.string() + "/penshape.sock"),
            std::string::npos)
      << out;
}

TEST(LiveCli, BadArgumentsExitWithTwo) {
  const std::vector<std::vector<std::string>> bad = {
      {"devices", "extra"},
      {"devices", "--socket", "a", "--address", "b"},
      {"devices", "--socket"},
      {"watch", "--count", "0"},
      {"watch", "--count", "1.5"},
      {"watch", "--duration", "-1"},
      {"watch", "--device", "a,,b"},
      {"watch", "--bogus"},
      {"record"},
      {"record", "a.txt", "b.txt"},
      {"record", "a.txt", "--samples", "x"},
  };
  for (const auto& args : bad) {
    const auto [code, out] = cli(args);
    EXPECT_EQ(code, 2) << args[0] << " " << (args.size() > 1 ? args[1] : "") << ": " << out;
    EXPECT_NE(out.find("see --help"), std::string::npos) << out;
  }
}

TEST(LiveCli, DevicesListsTheAttachedTablets) {
  TestDaemon daemon("devices");
  {
    const auto [code, out] = cli({"devices", "--address", daemon.address});
    EXPECT_EQ(code, 0) << out;
    EXPECT_NE(out.find("no tablets attached"), std::string::npos) << out;
  }
  daemon.source->attach("pen-a");
  daemon.source->attach("pen-b");
  {
    const auto [code, out] = cli({"devices", "--address", daemon.address});
    EXPECT_EQ(code, 0) << out;
    const auto rows = lines(out);
    ASSERT_EQ(rows.size(), 2U) << out;
    EXPECT_EQ(rows[0].rfind("pen-a  056a:0357  Clients Test Tablet  200.0 x 125.0 mm", 0), 0U)
        << out;
    EXPECT_NE(rows[1].find("/dev/test-pen-b"), std::string::npos) << out;
  }
  {
    const auto [code, out] = cli({"devices", "--json", "--address", daemon.address});
    EXPECT_EQ(code, 0) << out;
    const auto rows = lines(out);
    ASSERT_EQ(rows.size(), 2U) << out;
    EXPECT_EQ(rows[0].rfind("{\"id\":\"pen-a\",\"settings_key\":\"056a:0357\"", 0), 0U) << out;
    EXPECT_NE(rows[0].find("\"width_mm\":200,\"height_mm\":125"), std::string::npos) << out;
    EXPECT_NE(rows[1].find("\"x_max\":40000"), std::string::npos) << out;
  }
}

// The square the test double snaps a stroke to, computed here from the samples.
std::vector<std::pair<double, double>> expected_square(const Stroke& stroke) {
  const BoxMm b = tip_box_mm(stroke);
  const double cx = (b.x0 + b.x1) / 2, cy = (b.y0 + b.y1) / 2;
  const double h = ((b.x1 - b.x0) + (b.y1 - b.y0)) / 4;
  return {{cx - h, cy - h}, {cx + h, cy - h}, {cx + h, cy + h}, {cx - h, cy + h}};
}

TEST(LiveCli, WatchPrintsStrokesAndShapesAsJsonLines) {
  TestDaemon daemon("watch-json");
  daemon.source->attach("pen-a");
  ChildProcess watch({kCli, "watch", "--json", "--count", "3", "--address", daemon.address});
  ASSERT_TRUE(watch.wait_for_output("subscribed to " + daemon.address)) << watch.output();
  const Stroke stroke = daemon.source->draw("pen-a", rectangle_samples());
  ASSERT_EQ(watch.wait(), 0) << watch.output();
  std::vector<std::string> events;
  for (const auto& line : lines(watch.output())) {
    if (line.rfind("{", 0) == 0) events.push_back(line);
  }
  ASSERT_EQ(events.size(), 3U) << watch.output();
  EXPECT_NE(events[0].find("\"device_id\":\"pen-a\",\"type\":\"stroke_started\""),
            std::string::npos);
  EXPECT_NE(events[1].find("\"type\":\"stroke_finished\",\"stroke_id\":1,\"samples\":" +
                           std::to_string(stroke.samples.size())),
            std::string::npos)
      << events[1];
  EXPECT_NE(events[2].find("\"type\":\"shape\",\"stroke_id\":1,\"shape\":{\"kind\":\"square\""),
            std::string::npos)
      << events[2];
  // The vertices, in mm, as the daemon sent them.
  const std::regex vertex(R"(\[(-?[0-9.e+-]+),(-?[0-9.e+-]+)\])");
  std::vector<std::pair<double, double>> got;
  for (auto it = std::sregex_iterator(events[2].begin(), events[2].end(), vertex);
       it != std::sregex_iterator(); ++it) {
    got.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
  }
  const auto want = expected_square(stroke);
  ASSERT_EQ(got.size(), want.size()) << events[2];
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_DOUBLE_EQ(got[i].first, want[i].first);
    EXPECT_DOUBLE_EQ(got[i].second, want[i].second);
  }
}

TEST(LiveCli, WatchPrintsReadableLinesWithSamples) {
  TestDaemon daemon("watch-text");
  daemon.source->attach("pen-a");
  const auto samples = rectangle_samples();
  // Hover + tip-down samples + tip up, stroke started/finished, shape.
  const std::size_t expected = samples.size() + 2 + 3;
  ChildProcess watch({kCli, "watch", "--samples", "--count", std::to_string(expected), "--address",
                      daemon.address});
  ASSERT_TRUE(watch.wait_for_output("subscribed to")) << watch.output();
  daemon.source->draw("pen-a", samples);
  ASSERT_EQ(watch.wait(), 0) << watch.output();
  const std::string out = watch.output();
  EXPECT_NE(out.find("[pen-a] stroke 1 started"), std::string::npos) << out;
  EXPECT_NE(
      out.find("[pen-a] stroke 1 finished, " + std::to_string(samples.size() + 1) + " samples"),
      std::string::npos)
      << out;
  EXPECT_NE(out.find("[pen-a] stroke 1 is a square with 4 vertices confidence 0.75"),
            std::string::npos)
      << out;
  const auto first = samples.front();
  EXPECT_NE(out.find("1 samples, last x=" + std::to_string(first.x) +
                     " y=" + std::to_string(first.y) + " pressure=4000 tip"),
            std::string::npos)
      << out;
}

TEST(LiveCli, WatchWritesOneSvgPerStroke) {
  TestDaemon daemon("watch-svg");
  daemon.source->attach("pen-a");
  const auto dir = temp_dir("svg") / "pictures";
  ChildProcess watch(
      {kCli, "watch", "--count", "3", "--svg-dir", dir.string(), "--address", daemon.address});
  ASSERT_TRUE(watch.wait_for_output("subscribed to")) << watch.output();
  const Stroke stroke = daemon.source->draw("pen-a", rectangle_samples());
  ASSERT_EQ(watch.wait(), 0) << watch.output();
  const auto file = dir / "stroke-pen-a-1.svg";
  ASSERT_TRUE(std::filesystem::exists(file)) << watch.output();
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const ptree doc = parse_xml(text);
  const ptree& svg = doc.get_child("svg");
  ASSERT_NE(find_by_id(svg, "ink"), nullptr);
  ASSERT_NE(find_by_id(svg, "band"), nullptr);
  ASSERT_NE(find_by_id(svg, "shape-ink"), nullptr);
  const ptree* samples = find_by_id(svg, "samples");
  ASSERT_NE(samples, nullptr);
  EXPECT_EQ(elements(*samples, "circle").size(), stroke.samples.size() - 1); // tip down only
  const ptree* shape = find_by_id(svg, "shape");
  ASSERT_NE(shape, nullptr);
  const auto paths = elements(*shape, "path");
  ASSERT_EQ(paths.size(), 1U);
  const auto cmds = parse_path(*attribute(*paths[0], "d"));
  ASSERT_EQ(cmds.size(), 5U); // M, 3 L, Z
  // The picture is in pixels: the scale comes from the ink polygon, the stroke's box grown by
  // the pen radius (1 mm) on each side.
  const auto ink = parse_path(*attribute(*elements(*find_by_id(svg, "ink"), "path")[0], "d"));
  ASSERT_EQ(ink.size(), 5U);
  const BoxMm box = tip_box_mm(stroke);
  const double s = std::abs(ink[1].args[0] - ink[0].args[0]) / (box.x1 - box.x0 + 2.0);
  const auto want = expected_square(stroke);
  const double side = (want[1].first - want[0].first) * s;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& a = cmds[i].args;
    const auto& b = cmds[(i + 1) % 4].args;
    EXPECT_NEAR(std::hypot(b[0] - a[0], b[1] - a[1]), side, 1e-2) << "edge " << i;
  }
  EXPECT_NE(text.find("<title>stroke 1, "), std::string::npos);
  EXPECT_NE(text.find(": square (H &lt;= "), std::string::npos);
}

TEST(LiveCli, WatchShowsDevicesAttachedAndDetached) {
  TestDaemon daemon("watch-devices");
  daemon.source->attach("pen-a");
  ChildProcess watch(
      {kCli, "watch", "--devices", "--json", "--count", "3", "--address", daemon.address});
  ASSERT_TRUE(watch.wait_for_output("\"type\":\"device_attached\"")) << watch.output();
  daemon.source->attach("pen-b");
  ASSERT_TRUE(watch.wait_for_output("/dev/test-pen-b")) << watch.output();
  daemon.source->detach("pen-a");
  ASSERT_EQ(watch.wait(), 0) << watch.output();
  const std::string out = watch.output();
  EXPECT_NE(out.find("\"device_id\":\"pen-a\",\"type\":\"device_attached\""), std::string::npos)
      << out;
  EXPECT_NE(out.find("\"device_id\":\"pen-b\",\"type\":\"device_attached\""), std::string::npos)
      << out;
  EXPECT_NE(out.find("\"device_id\":\"pen-a\",\"type\":\"device_detached\""), std::string::npos)
      << out;
}

TEST(LiveCli, WatchEndsCleanlyWhenTheDaemonStopsOrOnCtrlC) {
  {
    TestDaemon daemon("watch-stop");
    ChildProcess watch({kCli, "watch", "--address", daemon.address});
    ASSERT_TRUE(watch.wait_for_output("subscribed to")) << watch.output();
    daemon.server->shutdown();
    EXPECT_EQ(watch.wait(), 0) << watch.output();
    EXPECT_NE(watch.output().find("penshaped stopped"), std::string::npos) << watch.output();
  }
  {
    TestDaemon daemon("watch-int");
    ChildProcess watch({kCli, "watch", "--address", daemon.address});
    ASSERT_TRUE(watch.wait_for_output("subscribed to")) << watch.output();
    watch.signal(SIGINT);
    EXPECT_EQ(watch.wait(), 0) << watch.output();
  }
}

// Reads the E: lines of a hid-recorder file: {time_us, bytes}.
struct Report {
  std::int64_t time_us;
  std::vector<unsigned> bytes;
};

TEST(LiveCli, RecordWritesAHidRecorderFileOfTheSamples) {
  TestDaemon daemon("record");
  daemon.source->attach("pen-a");
  const auto file = temp_dir("record") / "pen.hid.txt";
  ChildProcess record(
      {kCli, "record", file.string(), "--decoded", "--strokes", "1", "--address", daemon.address});
  ASSERT_TRUE(record.wait_for_output("recording pen-a into")) << record.output();
  const Stroke stroke = daemon.source->draw("pen-a", rectangle_samples());
  ASSERT_EQ(record.wait(), 0) << record.output();

  std::ifstream in(file);
  std::vector<unsigned> descriptor;
  std::vector<Report> reports;
  std::string name;
  std::string ids;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line.substr(std::min<std::size_t>(3, line.size())));
    if (line.rfind("R: ", 0) == 0) {
      std::size_t n = 0;
      fields >> n;
      for (unsigned b = 0; fields >> std::hex >> b;) descriptor.push_back(b);
      EXPECT_EQ(descriptor.size(), n) << line;
    } else if (line.rfind("N: ", 0) == 0) {
      name = line.substr(3);
    } else if (line.rfind("I: ", 0) == 0) {
      ids = line.substr(3);
    } else if (line.rfind("E: ", 0) == 0) {
      std::string stamp;
      std::size_t n = 0;
      fields >> stamp >> n;
      const auto dot = stamp.find('.');
      Report r{std::stoll(stamp.substr(0, dot)) * 1'000'000 + std::stoll(stamp.substr(dot + 1)),
               {}};
      for (unsigned b = 0; fields >> std::hex >> b;) r.bytes.push_back(b);
      EXPECT_EQ(r.bytes.size(), n) << line;
      reports.push_back(r);
    }
  }
  EXPECT_EQ(name, "Clients Test Tablet");
  EXPECT_EQ(ids, "3 056a 0357");
  // A HID digitizer pen application collection (usage page 0x0D, usage 0x02).
  ASSERT_GE(descriptor.size(), 6U);
  EXPECT_EQ((std::vector<unsigned>(descriptor.begin(), descriptor.begin() + 6)),
            (std::vector<unsigned>{0x05, 0x0d, 0x09, 0x02, 0xa1, 0x01}));
  // Every sample of the stroke plus the hover sample before it, in order (layout documented in
  // hid_recording_writer.hpp).
  ASSERT_EQ(reports.size(), stroke.samples.size() + 1) << record.output();
  auto le32 = [](const std::vector<unsigned>& b, std::size_t at) {
    return static_cast<std::int64_t>(b[at] | b[at + 1] << 8U | b[at + 2] << 16U | b[at + 3] << 24U);
  };
  const std::int64_t t0 = stroke.samples.front().time_us - 1000; // the hover sample
  EXPECT_EQ(reports[0].time_us, 0);
  for (std::size_t i = 0; i < stroke.samples.size(); ++i) {
    const PenSample& s = stroke.samples[i];
    const Report& r = reports[i + 1];
    ASSERT_EQ(r.bytes.size(), 16U);
    EXPECT_EQ(r.bytes[0], 2U);
    EXPECT_EQ((r.bytes[1] & 1U) != 0, s.tip) << i;
    EXPECT_EQ((r.bytes[1] & 16U) != 0, s.in_range) << i;
    EXPECT_EQ(le32(r.bytes, 2), s.x) << i;
    EXPECT_EQ(le32(r.bytes, 6), s.y) << i;
    EXPECT_EQ(le32(r.bytes, 10), s.pressure) << i;
    EXPECT_EQ(r.time_us, s.time_us - t0) << i;
  }
}

TEST(LiveCli, RecordedFileReplaysToTheSameSamples) {
  TestDaemon daemon("record-replay");
  daemon.source->attach("pen-a");
  const auto file = temp_dir("replay") / "pen.hid.txt";
  ChildProcess record(
      {kCli, "record", file.string(), "--decoded", "--strokes", "1", "--address", daemon.address});
  ASSERT_TRUE(record.wait_for_output("recording pen-a into")) << record.output();
  const Stroke stroke = daemon.source->draw("pen-a", rectangle_samples());
  ASSERT_EQ(record.wait(), 0) << record.output();
  // The drivers' HID decoder (penshape replay --local) reads the synthetic descriptor and gives
  // back every sample: the hover sample, then the stroke.
  // stdout only: its summary on stderr would interleave with the JSON lines in one pipe.
  const auto [code, out] = run_program(
      {"/bin/sh", "-c", kCli + " replay --local '" + file.string() + "' --json 2>/dev/null"});
  ASSERT_EQ(code, 0) << out;
  const std::regex sample(
      R"re(\{"t":[0-9.e+-]+,"x":(-?\d+),"y":(-?\d+),"pressure":(\d+),"tilt_x":-?\d+,"tilt_y":-?\d+,"tip":(true|false),"in_range":(true|false))re");
  std::vector<PenSample> replayed;
  for (const auto& line : lines(out)) {
    std::smatch m;
    if (!std::regex_search(line, m, sample)) continue;
    PenSample p;
    p.x = std::stoi(m[1]);
    p.y = std::stoi(m[2]);
    p.pressure = static_cast<std::uint32_t>(std::stoul(m[3]));
    p.tip = m[4] == "true";
    p.in_range = m[5] == "true";
    replayed.push_back(p);
  }
  ASSERT_EQ(replayed.size(), stroke.samples.size() + 1) << out;
  for (std::size_t i = 0; i < stroke.samples.size(); ++i) {
    const PenSample& want = stroke.samples[i];
    const PenSample& got = replayed[i + 1];
    EXPECT_EQ(got.x, want.x) << i;
    EXPECT_EQ(got.y, want.y) << i;
    EXPECT_EQ(got.pressure, want.pressure) << i;
    EXPECT_EQ(got.tip, want.tip) << i;
    EXPECT_EQ(got.in_range, want.in_range) << i;
  }
  EXPECT_NE(out.find("{\"stroke\":1,"), std::string::npos) << out;
}

// The real penshaped replaying a tablet recording (generated in the Wacom PenPartner's protocol) as
// a live device: watch sees the device and its strokes, with the samples the drivers' offline
// decoder finds in the same file.
TEST(LiveCli, WatchAgainstTheRealDaemonReplayingARealCapture) {
  const std::string capture = (test::recordings_dir() / "generated-graphire.hidrec").string();
  const std::string address = unique_test_address("real-replay");
  ChildProcess daemon({PENSHAPED, "--listen", address, "--replay", capture, "--replay-delay", "3"});
  ASSERT_TRUE(daemon.wait_for_output("listening on")) << daemon.output();
  ChildProcess watch({kCli, "watch", "--devices", "--json", "--count", "3", "--duration", "60",
                      "--address", address}); // bounded: a stalled replay fails, never hangs
  ASSERT_EQ(watch.wait(), 0) << watch.output() << daemon.output();
  daemon.signal(SIGTERM);
  EXPECT_EQ(daemon.wait(), 0) << daemon.output();
  std::vector<std::string> events;
  for (const auto& line : lines(watch.output())) {
    if (line.rfind("{", 0) == 0) events.push_back(line);
  }
  ASSERT_EQ(events.size(), 3U) << watch.output();
  EXPECT_NE(events[0].find("\"type\":\"device_attached\""), std::string::npos) << events[0];
  EXPECT_NE(events[0].find("\"replay\":true"), std::string::npos) << events[0];
  EXPECT_NE(events[0].find("\"vendor_id\":1386,\"product_id\":97"), std::string::npos)
      << events[0]; // 056a:0061 from the I: line
  EXPECT_NE(events[1].find("\"type\":\"stroke_started\""), std::string::npos) << events[1];
  // The first stroke, as the drivers' offline decoder counts it in the same file.
  const auto [code, out] =
      run_program({"/bin/sh", "-c", kCli + " replay --local '" + capture + "' --json 2>/dev/null"});
  ASSERT_EQ(code, 0) << out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, std::regex(R"re(\{"stroke":1,[^}]*"samples":(\d+)\})re")))
      << out;
  EXPECT_NE(events[2].find(
                "\"type\":\"stroke_finished\",\"stroke_id\":1,\"samples\":" + m[1].str() + ","),
            std::string::npos)
      << events[2] << " vs offline " << m[0];
}

// `penshape replay FILE`: through the real penshaped when it answers (each stroke's shape as the
// daemon certifies it), locally otherwise; stderr says which.
TEST(LiveCli, ReplayGoesThroughTheDaemonWhenItRunsAndLocallyOtherwise) {
  const std::string recording = (test::recordings_dir() / "generated-shapes.hidrec").string();
  {
    const auto [code, out] =
        run_program({kCli, "replay", recording, "--address", unique_test_address("none")});
    EXPECT_EQ(code, 0) << out;
    EXPECT_NE(out.find("penshape replay: local: penshaped does not answer"), std::string::npos)
        << out;
    EXPECT_EQ(out.find("  shape: "), std::string::npos) << out;
  }
  const std::string address = unique_test_address("replay-through");
  ChildProcess daemon({PENSHAPED, "--listen", address});
  ASSERT_TRUE(daemon.wait_for_output("listening on")) << daemon.output();
  const auto [code, out] = run_program({kCli, "replay", recording, "--address", address});
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("through penshaped at " + address), std::string::npos) << out;
  // One shape per stroke, and the classes the recording's expectations accept for each.
  std::vector<std::string> shapes;
  for (const auto& line : lines(out)) {
    if (line.rfind("  shape: ", 0) == 0) shapes.push_back(line.substr(9));
  }
  std::vector<std::string> expected;
  for (const auto& line :
       lines(test::read_file(test::recordings_dir() / "generated-shapes.expected"))) {
    if (!line.empty() && line[0] != '#') expected.push_back(line);
  }
  ASSERT_EQ(shapes.size(), expected.size()) << out;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const std::string kind = shapes[i].substr(0, shapes[i].find(' '));
    EXPECT_NE(("|" + expected[i] + "|").find("|" + kind + "|"), std::string::npos)
        << "stroke " << i + 1 << ": " << shapes[i] << " vs " << expected[i];
  }
  const auto [local_code, local] =
      run_program({kCli, "replay", "--local", recording, "--address", address});
  EXPECT_EQ(local_code, 2) << local; // --local takes no daemon address
  daemon.signal(SIGTERM);
  EXPECT_EQ(daemon.wait(), 0) << daemon.output();
}

TEST(LiveCli, RecordRefusesWhatItCannotRecord) {
  TestDaemon daemon("record-errors");
  {
    const auto [code, out] = cli({"record", "/dev/null", "--address", daemon.address});
    EXPECT_EQ(code, 1) << out;
    EXPECT_NE(out.find("no tablets are attached"), std::string::npos) << out;
  }
  daemon.source->attach("pen-a");
  daemon.source->attach("pen-b");
  {
    const auto [code, out] = cli({"record", "/dev/null", "--address", daemon.address});
    EXPECT_EQ(code, 1) << out;
    EXPECT_NE(out.find("choose one with --device"), std::string::npos) << out;
  }
  {
    const auto [code, out] =
        cli({"record", "/dev/null", "--device", "pen-z", "--address", daemon.address});
    EXPECT_EQ(code, 1) << out;
    EXPECT_NE(out.find("no device 'pen-z'"), std::string::npos) << out;
  }
  {
    const auto [code, out] = cli({"record", "/nonexistent-dir/x.txt", "--device", "pen-a",
                                  "--decoded", "--address", daemon.address});
    EXPECT_EQ(code, 2) << out;
    EXPECT_NE(out.find("cannot write /nonexistent-dir/x.txt"), std::string::npos) << out;
  }
}

TEST(LiveCli, RecordStopsWhenTheTabletIsUnplugged) {
  TestDaemon daemon("record-detach");
  daemon.source->attach("pen-a");
  const auto file = temp_dir("detach") / "pen.hid.txt";
  ChildProcess record({kCli, "record", file.string(), "--decoded", "--address", daemon.address});
  ASSERT_TRUE(record.wait_for_output("recording pen-a into")) << record.output();
  daemon.source->draw("pen-a", rectangle_samples());
  daemon.source->detach("pen-a");
  EXPECT_EQ(record.wait(), 0) << record.output();
  EXPECT_NE(record.output().find("(the tablet was unplugged)"), std::string::npos)
      << record.output();
}

} // namespace
} // namespace penshape::testing
