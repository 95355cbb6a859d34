// `penshape record` captures the device's own bytes: the real penshaped replays the bundled
// PenPartner capture (recordings/generated-graphire.hidrec) as a live tablet, the real `penshape`
// binary records it over a unix-abstract socket, and the file must hold the same descriptor, ids
// and every report in the same order with the same times; replayed offline it gives the same
// strokes as the original. Also: --strokes ends the file with the report that ended the stroke,
// a daemon without raw reports gets a clear refusal (and --decoded still works), bad usage is 2.
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "child_process.hpp"
#include "penshape/drivers/recording.hpp"
#include "test_daemon.hpp"

namespace penshape::testing {
namespace {

namespace fs = std::filesystem;

const std::string kCli = PENSHAPE_CLI;
const std::string kOriginal =
    std::string(PENSHAPE_SOURCE_DIR) + "/recordings/generated-graphire.hidrec";

fs::path temp_dir(const std::string& name) {
  auto dir = fs::temp_directory_path() /
             ("penshape-record-raw-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> lines_starting(const fs::path& file, const std::string& prefix) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) == 0) out.push_back(line);
  }
  return out;
}

// `E: sec.usec …` → microseconds.
std::int64_t event_time_us(const std::string& line) {
  std::istringstream fields(line.substr(3));
  std::string stamp;
  fields >> stamp;
  const auto dot = stamp.find('.');
  return std::stoll(stamp.substr(0, dot)) * 1'000'000 + std::stoll(stamp.substr(dot + 1));
}

// `penshape replay --local FILE --json`: its JSON lines (samples and strokes), stdout only.
std::vector<std::string> replay_lines(const fs::path& file) {
  const auto [code, out] = run_program(
      {"/bin/sh", "-c", kCli + " replay --local '" + file.string() + "' --json 2>/dev/null"});
  EXPECT_EQ(code, 0) << out;
  std::vector<std::string> lines;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind('{', 0) == 0) lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> strokes_of(const std::vector<std::string>& replay) {
  std::vector<std::string> out;
  for (const auto& line : replay) {
    if (line.rfind("{\"stroke\":", 0) == 0) out.push_back(line);
  }
  return out;
}

// penshaped replaying the original at its recorded pace after `delay` seconds, and `penshape
// record --wait` subscribed before that: the capture starts with the tablet's first report.
struct RecordedReplay {
  RecordedReplay(const std::string& tag, const std::vector<std::string>& record_options)
      : address(unique_test_address(tag)),
        file(temp_dir(tag) / "capture.hid.txt"),
        daemon({PENSHAPED, "--listen", address, "--replay", kOriginal, "--replay-delay", "6"}) {
    if (!daemon.wait_for_output("listening on")) return;
    std::vector<std::string> argv{kCli, "record", file.string(), "--wait", "--address", address};
    argv.insert(argv.end(), record_options.begin(), record_options.end());
    record = std::make_unique<ChildProcess>(argv);
    subscribed_in_time = record->wait_for_output("waiting for a tablet") &&
                         daemon.output().find("replaying") == std::string::npos;
    exit_code = record->wait();
    daemon.signal(SIGTERM);
    daemon_exit_code = daemon.wait();
  }
  ~RecordedReplay() {
    std::error_code ignored;
    fs::remove_all(file.parent_path(), ignored);
  }
  RecordedReplay(const RecordedReplay&) = delete;
  RecordedReplay& operator=(const RecordedReplay&) = delete;
  std::string address;
  fs::path file;
  ChildProcess daemon;
  std::unique_ptr<ChildProcess> record;
  bool subscribed_in_time = false;
  int exit_code = -1;
  int daemon_exit_code = -1;
};

TEST(RecordRawCli, CapturesTheDevicesOwnDescriptorAndEveryReport) {
  RecordedReplay run("all", {"--duration", "120"});
  ASSERT_NE(run.record, nullptr) << run.daemon.output();
  ASSERT_TRUE(run.subscribed_in_time) << run.record->output() << run.daemon.output();
  ASSERT_EQ(run.exit_code, 0) << run.record->output() << run.daemon.output();
  EXPECT_EQ(run.daemon_exit_code, 0) << run.daemon.output();
  EXPECT_NE(run.record->output().find("(the tablet was unplugged)"), std::string::npos)
      << run.record->output();

  // The header lines, textually: the same descriptor, name, physical path and ids.
  for (const std::string prefix : {"R: ", "N: ", "P: ", "I: "}) {
    EXPECT_EQ(lines_starting(run.file, prefix), lines_starting(kOriginal, prefix)) << prefix;
  }
  // Every report, in order, with the same bytes and the same times (the replay clock is the
  // recording's own, and both files start at their first report).
  const auto original = lines_starting(kOriginal, "E: ");
  const auto captured = lines_starting(run.file, "E: ");
  ASSERT_GT(original.size(), 500U);
  ASSERT_EQ(captured.size(), original.size());
  for (std::size_t i = 0; i < original.size(); ++i) {
    ASSERT_EQ(captured[i], original[i]) << "report " << i;
    if (i > 0) {
      ASSERT_LE(event_time_us(captured[i - 1]), event_time_us(captured[i])) << i;
    }
  }
  EXPECT_EQ(event_time_us(captured.front()), 0);
  // Parsed, it is the same device and stream.
  const drivers::Recording want = drivers::read_hid_recorder(drivers::read_file(kOriginal));
  const drivers::Recording got = drivers::read_hid_recorder(drivers::read_file(run.file));
  EXPECT_EQ(got, want);

  // Replayed offline through the drivers' decode path: the same samples and strokes.
  const auto replay_original = replay_lines(kOriginal);
  const auto replay_captured = replay_lines(run.file);
  ASSERT_GT(strokes_of(replay_original).size(), 1U);
  EXPECT_EQ(strokes_of(replay_captured), strokes_of(replay_original));
  EXPECT_EQ(replay_captured, replay_original);
}

TEST(RecordRawCli, StrokesEndsTheFileWithTheReportThatEndedTheStroke) {
  RecordedReplay run("strokes", {"--strokes", "2"});
  ASSERT_NE(run.record, nullptr) << run.daemon.output();
  ASSERT_TRUE(run.subscribed_in_time) << run.record->output() << run.daemon.output();
  ASSERT_EQ(run.exit_code, 0) << run.record->output() << run.daemon.output();

  const auto original = lines_starting(kOriginal, "E: ");
  const auto captured = lines_starting(run.file, "E: ");
  ASSERT_FALSE(captured.empty());
  ASSERT_LT(captured.size(), original.size());
  for (std::size_t i = 0; i < captured.size(); ++i) {
    ASSERT_EQ(captured[i], original[i]) << "report " << i; // a prefix of the device's stream
  }
  // Offline, the capture holds exactly the first two strokes of the original, and its last
  // report is the one that ended the second (the last sample of that stroke).
  const auto strokes_original = strokes_of(replay_lines(kOriginal));
  const auto strokes_captured = strokes_of(replay_lines(run.file));
  ASSERT_GE(strokes_original.size(), 3U);
  ASSERT_EQ(strokes_captured.size(), 2U);
  EXPECT_EQ(strokes_captured[0], strokes_original[0]);
  EXPECT_EQ(strokes_captured[1], strokes_original[1]);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(strokes_original[1], m, std::regex(R"re("t_end":([0-9.e+-]+))re")))
      << strokes_original[1];
  EXPECT_NEAR(static_cast<double>(event_time_us(captured.back())) / 1e6, std::stod(m[1]), 1e-6);
}

TEST(RecordRawCli, RefusesADaemonWithoutRawReportsUnlessDecoded) {
  TestDaemon daemon("record-raw-old"); // its scripted tablet has no HID descriptor
  daemon.source->attach("pen-a");
  const fs::path file = temp_dir("old") / "capture.hid.txt";
  {
    const auto [code, out] =
        run_program({kCli, "record", file.string(), "--address", daemon.address});
    EXPECT_EQ(code, 1) << out;
    EXPECT_NE(out.find("gives no HID report descriptor for 'pen-a'"), std::string::npos) << out;
    EXPECT_NE(out.find("--decoded"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(file)); // refused before touching FILE
  }
  ChildProcess record(
      {kCli, "record", file.string(), "--decoded", "--strokes", "1", "--address", daemon.address});
  ASSERT_TRUE(record.wait_for_output("recording pen-a into")) << record.output();
  PenSample s;
  s.x = 100;
  s.y = 200;
  s.pressure = 50;
  s.in_range = true;
  s.tip = true;
  std::vector<PenSample> down;
  for (int i = 0; i < 5; ++i) {
    s.time_us = 10'000 + i * 5'000;
    s.x += 30;
    down.push_back(s);
  }
  daemon.source->draw("pen-a", down);
  ASSERT_EQ(record.wait(), 0) << record.output();
  EXPECT_EQ(lines_starting(file, "E: ").size(), down.size() + 2); // hover, stroke, tip up
  fs::remove_all(file.parent_path());
}

// penshaped configured to take no raw subscriber: the capture is refused with the daemon's
// reason and leaves no file behind.
TEST(RecordRawCli, ARefusedSubscriptionLeavesNoFile) {
  const fs::path dir = temp_dir("refused");
  const fs::path config = dir / "penshaped.conf";
  std::ofstream(config) << "max_raw_report_subscribers = 0\n";
  const std::string address = unique_test_address("refused");
  ChildProcess daemon(
      {PENSHAPED, "--config", config.string(), "--listen", address, "--replay", kOriginal});
  ASSERT_TRUE(daemon.wait_for_output("replaying")) << daemon.output();
  const fs::path file = dir / "capture.hid.txt";
  const auto [code, out] = run_program({kCli, "record", file.string(), "--address", address});
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find("max_raw_report_subscribers = 0"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(file));
  daemon.signal(SIGTERM);
  EXPECT_EQ(daemon.wait(), 0) << daemon.output();
  fs::remove_all(dir);
}

TEST(RecordRawCli, WaitStopsCleanlyWhenNoTabletComes) {
  TestDaemon daemon("record-raw-none");
  const fs::path file = temp_dir("none") / "capture.hid.txt";
  ChildProcess record({kCli, "record", file.string(), "--wait", "--address", daemon.address});
  ASSERT_TRUE(record.wait_for_output("waiting for a tablet")) << record.output();
  record.signal(SIGINT);
  EXPECT_EQ(record.wait(), 1) << record.output();
  EXPECT_NE(record.output().find("no tablet was attached; nothing recorded"), std::string::npos)
      << record.output();
  EXPECT_FALSE(fs::exists(file));
  fs::remove_all(file.parent_path());
}

TEST(RecordRawCli, BadUsageExitsWithTwo) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"record", "a.txt", "--samples", "5"},
        {"record", "a.txt", "--wait", "--decoded"},
        {"record", "a.txt", "--strokes", "0"},
        {"record", "a.txt", "--duration", "-1"}}) {
    std::vector<std::string> argv{kCli};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto [code, out] = run_program(argv);
    EXPECT_EQ(code, 2) << args[2] << ": " << out;
  }
  const auto [code, out] = run_program({kCli, "record", "--help"});
  EXPECT_EQ(code, 0);
  for (const char* option : {"--device", "--duration", "--strokes", "--wait", "--decoded"}) {
    EXPECT_NE(out.find(option), std::string::npos) << option;
  }
}

} // namespace
} // namespace penshape::testing
