#include "json_writer.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace penshape::cli {
namespace {

TEST(JsonWriter, NestedValuesAndCommas) {
  JsonWriter j;
  j.begin_object();
  j.key("a").integer(1);
  j.key("b").begin_array().number(0.5).boolean(true).null().end_array();
  j.key("c").begin_object().key("d").string("x").end_object();
  j.end_object();
  EXPECT_EQ(j.str(), R"({"a":1,"b":[0.5,true,null],"c":{"d":"x"}})");
}

TEST(JsonWriter, EscapesAndNonFinite) {
  JsonWriter j;
  j.begin_array();
  j.string("q\"b\\n\n\x01");
  j.number(std::numeric_limits<double>::quiet_NaN());
  j.number(0.1);
  j.end_array();
  EXPECT_EQ(j.str(), "[\"q\\\"b\\\\n\\n\\u0001\",null,0.1]");
}

} // namespace
} // namespace penshape::cli
