// The JSON reader penshape verify uses: values and numbers as written, JSON lines, escapes, and
// errors that name line and column (never a crash, even on deep nesting).
#include <gtest/gtest.h>

#include <string>

#include "json_value.hpp"
#include "json_writer.hpp"

namespace penshape::cli {
namespace {

TEST(JsonReader, ReadsWhatTheWriterWrites) {
  JsonWriter w;
  w.begin_object();
  w.key("answer").string("YES \"quoted\"\n");
  w.key("xs").begin_array().number(0.1).number(-2.5e-300).integer(7).end_array();
  w.key("ok").boolean(true);
  w.key("none").null();
  w.end_object();
  const auto values = parse_json_values(w.str());
  ASSERT_EQ(values.size(), 1U);
  const JsonValue& v = values[0];
  ASSERT_NE(v.find("answer"), nullptr);
  EXPECT_EQ(v.find("answer")->text, "YES \"quoted\"\n");
  const JsonValue* xs = v.find("xs");
  ASSERT_NE(xs, nullptr);
  ASSERT_EQ(xs->items.size(), 3U);
  EXPECT_EQ(xs->items[0].text, "0.1"); // the digits as written: read exactly later
  EXPECT_EQ(xs->items[1].text, "-2.5e-300");
  EXPECT_EQ(xs->items[2].text, "7");
  EXPECT_TRUE(v.find("ok")->boolean);
  EXPECT_EQ(v.find("none")->kind, JsonValue::Kind::kNull);
  EXPECT_EQ(v.find("missing"), nullptr);
}

TEST(JsonReader, JsonLinesGiveOneValueEach) {
  const auto values = parse_json_values("{\"a\":1}\n{\"a\":2}\n\n[3]\n");
  ASSERT_EQ(values.size(), 3U);
  EXPECT_EQ(values[1].find("a")->text, "2");
  EXPECT_EQ(values[2].items[0].text, "3");
  EXPECT_TRUE(parse_json_values(" \n ").empty());
}

TEST(JsonReader, ErrorsNameLineAndColumn) {
  for (const char* bad : {"{\"a\": }", "{\"a\" 1}", "[1, 2", "\"open", "{\"a\": 01x}", "nul",
                          "[1.]", "[1e]", "\"\\q\"", "\"\\u00zz\""}) {
    EXPECT_THROW((void)parse_json_values(bad), JsonError) << bad;
  }
  try {
    (void)parse_json_values("{\"a\": 1,\n  \"b\": ]}");
    FAIL() << "no error";
  } catch (const JsonError& e) {
    EXPECT_NE(std::string(e.what()).find("JSON line 2, column 8"), std::string::npos) << e.what();
  }
}

// nlohmann's parser reads one value at a time: values must be whole and apart, numbers keep the
// exact text they were written with (verify reads decimals as rationals).
TEST(JsonReader, ValuesAreWholeAndNumbersKeepTheirText) {
  const auto values = parse_json_values(
      "12 3\n1.50e+3 -0.1000000000000000055511151231257827\n"
      "{\"a\": [18446744073709551616]}");
  ASSERT_EQ(values.size(), 5U);
  EXPECT_EQ(values[0].text, "12");
  EXPECT_EQ(values[1].text, "3");
  EXPECT_EQ(values[2].text, "1.50e+3");
  EXPECT_EQ(values[3].text, "-0.1000000000000000055511151231257827");
  EXPECT_EQ(values[4].find("a")->items[0].text, "18446744073709551616");
  for (const char* bad : {"1x", "[1]x", "truex", "{} ]", "1 2 ,"}) {
    EXPECT_THROW((void)parse_json_values(bad), JsonError) << bad;
  }
}

TEST(JsonReader, DeepNestingIsAnErrorNotACrash) {
  EXPECT_THROW((void)parse_json_values(std::string(100000, '[')), JsonError);
}

} // namespace
} // namespace penshape::cli
