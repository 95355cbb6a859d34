// Exact reading of numbers in polygon text: the plain-decimal fast path (issue 26) gives the
// same exact rationals, in lowest terms, as the general reader, and malformed text keeps its
// error.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "penshape/core/polygon_io.hpp"

namespace penshape {
namespace {

// Lowest terms with a positive denominator: what the rest of the library assumes.
bool canonical(const Rational& v) {
  return sgn(v.get_den()) > 0 && gcd(v.get_num(), v.get_den()) == 1;
}

Rational pow10(unsigned long k) {
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 10, k);
  return Rational(p);
}

TEST(NumberText, DecimalsThatAreNotDoublesAreExact) {
  EXPECT_EQ(parse_rational("0.1"), Rational(1, 10));
  EXPECT_EQ(parse_rational("-0.30000000000000004"),
            Rational(-30000000000000004) / pow10(17)); // the double nearest 0.3 + 0.1 is not it
  EXPECT_EQ(parse_rational("1234567890.123456789"),    // 19 digits: the longest fast one
            Rational(mpz_class("1234567890123456789")) / pow10(9));
  EXPECT_EQ(parse_rational("9999999999999999999"), Rational(mpz_class("9999999999999999999")));
  EXPECT_EQ(parse_rational("12345678901234567890.5"), // 21 digits: the general reader
            Rational(mpz_class("123456789012345678905")) / 10);
  EXPECT_EQ(parse_rational("-0.000"), Rational(0));
  EXPECT_EQ(parse_rational("+2.50"), Rational(5, 2));
  EXPECT_EQ(parse_rational("1."), Rational(1));
  EXPECT_EQ(parse_rational(".5"), Rational(1, 2));
  for (const char* text : {"0.1", "-2.50", "0.000", "1234567890.123456789", "640.0009765625"}) {
    EXPECT_TRUE(canonical(parse_rational(text))) << text;
  }
}

// Random plain decimals against the same digits with an exponent (which takes the general
// reader): equal exact values.
TEST(NumberText, FastPathAgreesWithTheGeneralReader) {
  std::mt19937 rng(26);
  std::uniform_int_distribution<int> digit(0, 9);
  std::uniform_int_distribution<int> length(1, 19);
  for (int round = 0; round < 2000; ++round) {
    const int n = length(rng);
    std::string digits;
    for (int i = 0; i < n; ++i) digits += static_cast<char>('0' + digit(rng));
    const int scale = std::uniform_int_distribution<int>(0, n)(rng);
    const std::size_t point = digits.size() - static_cast<std::size_t>(scale);
    std::string plain(round % 3 == 0 ? "-" : "");
    std::string general_text = plain;
    plain.append(digits, 0, point);
    plain.push_back('.');
    plain.append(digits, point);
    general_text.append(digits);
    general_text.append("e-");
    general_text.append(std::to_string(scale));
    const Rational fast = parse_rational(plain);
    const Rational general = parse_rational(general_text);
    EXPECT_EQ(fast, general) << plain;
    EXPECT_TRUE(canonical(fast)) << plain;
  }
}

TEST(NumberText, HugeExponentsAreExactOrRefused) {
  EXPECT_EQ(parse_rational("1e400"), pow10(400));
  EXPECT_EQ(parse_rational("-25e-400"), Rational(-1, 4) / pow10(398));
  EXPECT_THROW(parse_rational("1e401"), InvalidInput);
  EXPECT_THROW(parse_rational("1e-99999999999999999999"), InvalidInput);
}

TEST(NumberText, MalformedNumbersKeepTheirErrors) {
  for (const char* bad :
       {"-", "+", ".", "..", "1..2", "1.2.", "-.", "1-", "+-1", "1 2", "1,5",
        "12345678901234567890x", "1234567890123456789.0.1", "0.1e", "1/", "/2", "1/-2", "e5"}) {
    EXPECT_THROW(parse_rational(bad), InvalidInput) << bad;
  }
  try {
    read_xy("0 0\n1 0\n1 0.5.5\n");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line, 3U);
    EXPECT_NE(std::string(e.what()).find("'0.5.5' is not a number"), std::string::npos) << e.what();
  }
  try {
    read_xy("0 0\n1 0 2 3\n");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("got 4 fields"), std::string::npos) << e.what();
  }
}

// Every white space character of the C locale separates fields, pads lines and blanks a line
// (the reader tests them itself since issue 26, without std::isspace).
TEST(NumberText, EveryWhiteSpaceCharacterSeparates) {
  const PolygonSet q = read_xy("\t0 \v0\r\n1\f0\n 1\t1 \n\n \t\v\f\r\n5 5\n6 5\n6 6\n");
  ASSERT_EQ(q.polygons.size(), 2U);
  ASSERT_EQ(q.polygons[0].outer.size(), 3U);
  EXPECT_EQ(q.polygons[0].outer[1].x, Rational(1));
  EXPECT_EQ(q.polygons[0].outer[2].y, Rational(1));
  EXPECT_EQ(q.polygons[1].outer.size(), 3U);
  EXPECT_THROW(read_xy("0 0\n1 0\n1\a1\n"), ParseError); // BEL is not white space
}

} // namespace
} // namespace penshape
