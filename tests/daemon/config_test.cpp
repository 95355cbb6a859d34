// penshaped's config file (config.hpp): every key, its range, errors naming the file, the line and
// the key; TOML syntax and the migration hints for the former format.
#include "penshape/daemon/config.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using penshape::daemon::ConfigError;
using penshape::daemon::parse_config;
using penshape::daemon::SnapTrigger;

std::string error_of(const std::string& text, const std::string& origin = "test.conf") {
  try {
    parse_config(text, origin);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Config, EmptyTextGivesTheDocumentedDefaults) {
  const auto config = parse_config("", "test.conf");
  EXPECT_EQ(config.listen, "");
  EXPECT_EQ(config.tcp, "");
  EXPECT_EQ(config.limits.max_subscribers, 128U);
  EXPECT_EQ(config.limits.subscriber_queue_events, 1024U);
  EXPECT_EQ(config.limits.max_message_bytes, 16U * 1024U * 1024U);
  EXPECT_EQ(config.limits.max_vertices, 200'000U);
  EXPECT_EQ(config.settings.pen_radius_mm, 1.0);
  EXPECT_EQ(config.settings.tolerance_fraction, 0.5);
  EXPECT_EQ(config.settings.precision_fraction, 0.125);
  EXPECT_TRUE(config.device_settings.empty());
}

TEST(Config, ReadsEveryKindOfLine) {
  const auto config = parse_config(
      "# a comment\n"
      "listen = \"unix:/run/x.sock\"   # trailing comment\n"
      "\n"
      "tcp = '127.0.0.1:7433'\n"
      "max_subscribers = 7\n"
      "subscriber_queue_events=9\n"
      "  pen_radius_mm = 0.75\n"
      "[device.\"056a:0010\"]\n"
      "pen_radius_mm = 2\r\n"
      "[ device . '28bd:0913' ]\n"
      "tolerance_fraction = 0.25\n",
      "test.conf");
  EXPECT_EQ(config.listen, "unix:/run/x.sock");
  EXPECT_EQ(config.tcp, "127.0.0.1:7433");
  EXPECT_EQ(config.limits.max_subscribers, 7U);
  EXPECT_EQ(config.limits.subscriber_queue_events, 9U);
  EXPECT_EQ(config.settings.pen_radius_mm, 0.75);
  ASSERT_EQ(config.device_settings.size(), 2U);
  EXPECT_EQ(config.device_settings.at("056a:0010").pen_radius_mm, 2.0);
  EXPECT_FALSE(config.device_settings.at("056a:0010").tolerance_fraction.has_value());
  EXPECT_EQ(config.device_settings.at("28bd:0913").tolerance_fraction, 0.25);
}

TEST(Config, ErrorsNameTheLineAndTheKey) {
  EXPECT_EQ(error_of("\n\nmax_subscribers = \"abc\"\n"),
            "test.conf:3: max_subscribers: expected an integer in 1..4096, got 'abc'");
  EXPECT_EQ(error_of("max_subscribers = 4.5"),
            "test.conf:1: max_subscribers: expected an integer in 1..4096, got '4.5'");
  EXPECT_EQ(error_of("max_subscribers = -1"),
            "test.conf:1: max_subscribers: expected an integer in 1..4096, got '-1'");
  EXPECT_EQ(error_of("max_subscribers = 0"),
            "test.conf:1: max_subscribers: expected an integer in 1..4096, got '0'");
  EXPECT_EQ(error_of("colour = 'blue'"), "test.conf:1: colour: unknown key");
  EXPECT_EQ(error_of("pen_radius_mm = 1\npen_radius_mm = 2"),
            "test.conf:2: pen_radius_mm: not TOML (column 17): Error while parsing key-value pair: "
            "cannot redefine existing integer 'pen_radius_mm'");
  EXPECT_EQ(error_of("pen_radius_mm = 100"),
            "test.conf:1: pen_radius_mm is 100, outside [0.05, 50]");
  EXPECT_EQ(error_of("pen_radius_mm = nan"),
            "test.conf:1: pen_radius_mm: expected a number, got 'nan'");
  EXPECT_EQ(error_of("pen_radius_mm = true"),
            "test.conf:1: pen_radius_mm: expected a number, got 'true'");
  EXPECT_EQ(error_of("listen = 3"), "test.conf:1: listen: expected a string in quotes, got '3'");
  EXPECT_EQ(error_of("snap_trigger = 'later'"),
            "test.conf:1: snap_trigger: expected pen_up, hold or both, got 'later'");
  EXPECT_EQ(error_of("\n[device.\"56a:10\"]"),
            "test.conf:2: device key '56a:10' is not vvvv:pppp (four lowercase hex digits each)");
  EXPECT_EQ(error_of("device = 1"),
            "test.conf:1: device: expected sections [device.\"vvvv:pppp\"]");
  EXPECT_EQ(error_of("[device]\npen_radius_mm = 1"),
            "test.conf:2: pen_radius_mm: expected a section [device.\"vvvv:pppp\"] (one per "
            "tablet model)");
  EXPECT_EQ(error_of("[printer]"),
            "test.conf:1: unknown section '[printer]' (expected [device.\"vvvv:pppp\"])");
  EXPECT_EQ(error_of("[device.\"056a:0010\"]\nmax_subscribers = 3"),
            "test.conf:2: max_subscribers: unknown key in a [device] section (pen_radius_mm, "
            "tolerance_fraction, precision_fraction, snap_trigger, hold_ms, hold_radius_mm, "
            "width_mm, height_mm)");
  EXPECT_EQ(error_of("tcp_allow_non_loopback = 'yes'"),
            "test.conf:1: tcp_allow_non_loopback: expected true or false, got 'yes'");
}

TEST(Config, TcpIsLoopbackOnlyUnlessAllowed) {
  EXPECT_NO_THROW(parse_config("tcp = \"127.0.0.1:1\"", "t"));
  EXPECT_NO_THROW(parse_config("tcp = \"[::1]:1\"", "t"));
  EXPECT_NO_THROW(parse_config("tcp = \"localhost:50051\"", "t"));
  EXPECT_EQ(error_of("\ntcp = \"0.0.0.0:50051\""),
            "test.conf:2: tcp: '0.0.0.0' is not a loopback address; set tcp_allow_non_loopback = "
            "true (or pass --tcp-allow-non-loopback) to listen beyond this machine");
  EXPECT_NO_THROW(parse_config("tcp = \"0.0.0.0:50051\"\ntcp_allow_non_loopback = true", "t"));
  EXPECT_EQ(error_of("tcp = \"127.0.0.1:99999\""),
            "test.conf:1: tcp: port '99999' is not in 0..65535");
  EXPECT_EQ(error_of("tcp = \"example.org:80\""),
            "test.conf:1: tcp: 'example.org' is not an IPv4 address, [IPv6] or localhost");
}

TEST(Config, MissingFileIsAnError) {
  EXPECT_THROW(penshape::daemon::load_config_file("/nonexistent/penshaped.conf"), ConfigError);
}

} // namespace

namespace {

TEST(Config, DeviceSectionsGiveAPhysicalSize) {
  const auto config = parse_config(
      "[device.\"28bd:0905\"]\n"
      "width_mm = 152.4\n"
      "height_mm = 95.25\n"
      "[device.\"256c:0064\"]\n"
      "pen_radius_mm = 0.8\n",
      "test.conf");
  ASSERT_EQ(config.device_sizes.size(), 1U);
  EXPECT_EQ(config.device_sizes.at("28bd:0905"), (std::pair<double, double>{152.4, 95.25}));
  EXPECT_EQ(config.device_settings.count("28bd:0905"), 1U); // a size alone makes a section
  EXPECT_EQ(config.device_sizes.count("256c:0064"), 0U);
}

TEST(Config, PhysicalSizeErrorsNameLineAndKey) {
  EXPECT_EQ(error_of("[device.\"28bd:0905\"]\nwidth_mm = 152\n"),
            "test.conf:2: height_mm: [device.\"28bd:0905\"] sets one of width_mm and height_mm: "
            "set both");
  EXPECT_EQ(error_of("[device.\"28bd:0905\"]\nwidth_mm = -1\nheight_mm = 3\n"),
            "test.conf:2: width_mm: expected millimetres in (0, 2000]");
  EXPECT_EQ(error_of("[device.\"28bd:0905\"]\nheight_mm = 'tall'\n"),
            "test.conf:2: height_mm: expected a number, got 'tall'");
  EXPECT_EQ(error_of("width_mm = 100\n"), "test.conf:1: width_mm: unknown key");
}

} // namespace

// The live grouping keys: the documented defaults (core's GroupingConfig), each key read, and
// out-of-range or misspelt values refused naming the line and the key.
TEST(Config, GroupingKeysAndTheirDefaults) {
  const auto defaults = parse_config("", "test.conf").grouping;
  EXPECT_TRUE(defaults.enabled);
  EXPECT_EQ(defaults.max_strokes, 4U);
  EXPECT_EQ(defaults.max_pause_seconds, 2.0);
  EXPECT_TRUE(defaults.tidy.axis);
  const auto config = parse_config(
      "grouping = false\n"
      "group_max_strokes = 3\n"
      "group_max_pause_s = 0.5\n"
      "tidy_circle = false\n"
      "tidy_right_angles = false\n"
      "tidy_equal_sides = false\n"
      "tidy_axis = false\n"
      "tidy_parallel = false\n"
      "tidy_connection = false\n",
      "test.conf");
  const auto& g = config.grouping;
  EXPECT_FALSE(g.enabled);
  EXPECT_EQ(g.max_strokes, 3U);
  EXPECT_EQ(g.max_pause_seconds, 0.5);
  EXPECT_FALSE(g.tidy.circle || g.tidy.right_angles || g.tidy.equal_sides || g.tidy.axis ||
               g.tidy.parallel || g.tidy.connection);
}

TEST(Config, BadGroupingValuesNameTheLineAndKey) {
  EXPECT_EQ(error_of("\ngroup_max_strokes = 9\n"),
            "test.conf:2: group_max_strokes: expected an integer in 1..8, got '9'");
  EXPECT_EQ(error_of("group_max_strokes = 0\n"),
            "test.conf:1: group_max_strokes: expected an integer in 1..8, got '0'");
  EXPECT_EQ(error_of("group_max_pause_s = -1\n"),
            "test.conf:1: group_max_pause_s is -1; expected seconds in [0, 60]");
  EXPECT_EQ(error_of("group_max_pause_s = 61\n"),
            "test.conf:1: group_max_pause_s is 61; expected seconds in [0, 60]");
  EXPECT_EQ(error_of("group_max_pause_s = nan\n"),
            "test.conf:1: group_max_pause_s: expected a number, got 'nan'");
  EXPECT_EQ(error_of("grouping = 'yes'\n"),
            "test.conf:1: grouping: expected true or false, got 'yes'");
  EXPECT_EQ(error_of("tidy_axes = true\n"), "test.conf:1: tidy_axes: unknown key");
  EXPECT_EQ(error_of("[device.\"056a:0010\"]\ngrouping = false\n"),
            "test.conf:2: grouping: unknown key in a [device] section (pen_radius_mm, "
            "tolerance_fraction, precision_fraction, snap_trigger, hold_ms, hold_radius_mm, "
            "width_mm, height_mm)");
}

// The config file is TOML: a full file as the README documents it, TOML syntax errors named by
// file, line and key, and the migration hints for files in the former `key = value` format.
namespace {

std::string toml_error_of(const std::string& text) { return error_of(text, "penshaped.conf"); }

TEST(ConfigToml, ReadsTheReadmeExample) {
  const auto config = parse_config(R"(# penshaped.conf
listen = "unix:/run/user/1000/penshape.sock"
tcp = "127.0.0.1:7433"            # tcp_allow_non_loopback = true to go beyond loopback
pen_radius_mm = 1.0               # r, in [0.05, 50]
tolerance_fraction = 0.5          # eps = fraction * r, in [0.01, 4]
precision_fraction = 0.125        # delta = fraction * eps, in [1/1024, 1/2]
max_subscribers = 128             # and the other limits below
grouping = true
group_max_strokes = 4
group_max_pause_s = 2.0
tidy_circle = true
tidy_right_angles = false
tidy_connection = true
snap_trigger = "hold"
hold_ms = 400
hold_radius_mm = 1.5
[device."056a:0010"]
pen_radius_mm = 0.8
snap_trigger = "pen_up"
[device."28bd:0905"]
width_mm = 152.4
height_mm = 95
)",
                                   "penshaped.conf");
  EXPECT_EQ(config.listen, "unix:/run/user/1000/penshape.sock");
  EXPECT_EQ(config.tcp, "127.0.0.1:7433");
  EXPECT_EQ(config.limits.max_subscribers, 128U);
  EXPECT_EQ(config.settings.snap_trigger, SnapTrigger::kHold);
  EXPECT_EQ(config.settings.hold_ms, 400.0); // an integer is a number too
  EXPECT_EQ(config.settings.hold_radius_mm, 1.5);
  EXPECT_TRUE(config.grouping.enabled);
  EXPECT_FALSE(config.grouping.tidy.right_angles);
  ASSERT_EQ(config.device_settings.size(), 2U);
  EXPECT_EQ(config.device_settings.at("056a:0010").pen_radius_mm, 0.8);
  EXPECT_EQ(config.device_settings.at("056a:0010").snap_trigger, SnapTrigger::kPenUp);
  EXPECT_EQ(config.device_sizes.at("28bd:0905"), (std::pair<double, double>{152.4, 95.0}));
}

TEST(ConfigToml, DottedKeysAndInlineTablesAreTheSameSections) {
  const auto config = parse_config(
      "device.\"056a:0010\".pen_radius_mm = 0.7\n"
      "device.\"28bd:0913\" = { tolerance_fraction = 0.25 }\n",
      "penshaped.conf");
  EXPECT_EQ(config.device_settings.at("056a:0010").pen_radius_mm, 0.7);
  EXPECT_EQ(config.device_settings.at("28bd:0913").tolerance_fraction, 0.25);
}

TEST(ConfigToml, SyntaxErrorsNameTheLineAndTheKey) {
  EXPECT_EQ(toml_error_of("pen_radius_mm = 1\ngrouping = yes\n"),
            "penshaped.conf:2: grouping: not TOML (column 12): Error while parsing value: could "
            "not determine value type");
  EXPECT_EQ(toml_error_of("# ok\n[device.\"056a:0010\"\n"),
            "penshaped.conf:2: not TOML (column 20): Error while parsing table header: expected "
            "']', saw '\\n'");
  EXPECT_EQ(toml_error_of("just words"),
            "penshaped.conf:1: not TOML (column 6): Error while parsing key-value pair: expected "
            "'=', saw 'w'");
  EXPECT_EQ(toml_error_of("listen = \"unix:/x"),
            "penshaped.conf:1: listen: not TOML (column 18): Error while parsing string: "
            "encountered end-of-file");
  // Never anything but a ConfigError, even for bytes that are not UTF-8.
  EXPECT_NE(toml_error_of("listen = \"\xff\""), "no error");
}

TEST(ConfigToml, FormerFormatSaysWhatToWriteInstead) {
  EXPECT_EQ(toml_error_of("listen = unix:/run/user/1000/penshape.sock\n"),
            "penshaped.conf:1: listen: write the value in quotes: listen = "
            "\"unix:/run/user/1000/penshape.sock\"\n"
            "penshaped.conf: the config file is TOML: strings in quotes, [device.\"vvvv:pppp\"] "
            "sections (README, \"Config file\")");
  // Every former-format line at once, numbers and booleans being TOML already.
  EXPECT_EQ(toml_error_of("# old\n"
                          "tcp = 127.0.0.1:7433   # loopback\n"
                          "pen_radius_mm = 1.0\n"
                          "snap_trigger = both\n"
                          "[device 056a:0010]\n"
                          "pen_radius_mm = 0.8\n"
                          "[device \"28bd:0905\"]\n"
                          "width_mm = 152\n"),
            "penshaped.conf:2: tcp: write the value in quotes: tcp = \"127.0.0.1:7433\"\n"
            "penshaped.conf:4: snap_trigger: write the value in quotes: snap_trigger = \"both\"\n"
            "penshaped.conf:5: [device 056a:0010]: write [device.\"056a:0010\"]\n"
            "penshaped.conf:7: [device \"28bd:0905\"]: write [device.\"28bd:0905\"]\n"
            "penshaped.conf: the config file is TOML: strings in quotes, [device.\"vvvv:pppp\"] "
            "sections (README, \"Config file\")");
  // A value with a quote or a backslash is written as a TOML string would hold it.
  EXPECT_EQ(toml_error_of("listen = unix:/a\\\"b\n").substr(0, 76),
            "penshaped.conf:1: listen: write the value in quotes: listen = \"unix:/a\\\\\\\"b\"");
}

} // namespace
