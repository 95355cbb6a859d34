// The one $1 gesture-log reader (clients/penshape/dollar_xml.hpp): points, names and times as
// written, and errors that name the file's line, never a crash.
#include "dollar_xml.hpp"

#include <gtest/gtest.h>

#include <string>

namespace penshape::dollar {
namespace {

TEST(DollarXml, ReadsNameSubjectAndPoints) {
  const Gesture g = parse_dollar_xml(
      "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n"
      "<Gesture Name=\"triangle03\" Subject=\"7\" Number=\"3\">\n"
      "  <Point X=\"10\" Y=\"-2.5\" T=\"1500\" />\n"
      "  <Point X=\"11\" Y=\"3\" />\n"
      "</Gesture>\n",
      "t.xml");
  EXPECT_EQ(g.name, "triangle03");
  EXPECT_EQ(g.kind(), "triangle");
  EXPECT_EQ(g.subject, "7");
  EXPECT_EQ(g.line, 2U);
  ASSERT_EQ(g.points.size(), 2U);
  EXPECT_EQ(g.points[0].x, 10);
  EXPECT_EQ(g.points[0].y, -2.5);
  EXPECT_EQ(g.points[0].t, 1.5);
  EXPECT_EQ(g.points[1].t, 0) << "T is optional";
}

TEST(DollarXml, ErrorsNameTheLine) {
  const std::pair<const char*, const char*> cases[] = {
      {"<Gesture Name=\"x\">\n<Point X=\"1\" Y=\"2\" ", "t.xml:2: unterminated"},
      {"<Gesture>\n<Point X=\"nan\" Y=\"2\"/>\n</Gesture>", "t.xml:2: attribute X=\"nan\""},
      {"<Gesture>\n\n<Point Y=\"2\"/></Gesture>", "t.xml:3: <Point> without attribute X"},
      {"<Gesture/>\n<Gesture/>", "t.xml:2: more than one <Gesture>"},
      {"<Other/>", "t.xml:1: <Other> where <Gesture> was expected"},
      {"", "no <Gesture> element"},
      {std::string("\xff\xfe\x00<", 4).c_str(), "t.xml:"},
  };
  for (const auto& [text, message] : cases) {
    try {
      (void)parse_dollar_xml(text, "t.xml");
      ADD_FAILURE() << "no error for " << text;
    } catch (const DollarXmlError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW((void)read_dollar_xml("/nonexistent/x.xml"), DollarXmlError);
}

} // namespace
} // namespace penshape::dollar
