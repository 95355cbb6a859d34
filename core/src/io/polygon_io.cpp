// Exact text readers for polygonal regions (x-y and WKT) and an exact WKT writer.
#include "penshape/core/polygon_io.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

namespace penshape {
namespace {

constexpr long kMaxExponent = 400;

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The C locale's white space, without std::isspace's call and locale lookup per character (it
// was 2% of reading a 200,000-vertex file).
constexpr bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

// Plain decimals [+-]digits[.digits] with at most 19 digits (so the digits, and 10^scale, fit in
// 64 bits), read without strings or big-number parsing: the value is m / 10^scale exactly, put in
// lowest terms by one gcd. False leaves `t` to the general reader (exponents, fractions, longer
// numbers, malformed text).
bool try_parse_plain_decimal(std::string_view t, Rational& out) {
  static_assert(sizeof(unsigned long) >= sizeof(std::uint64_t), "mpz_set_ui takes 64 bits");
  constexpr int kMaxDigits = 19; // 10^19 < 2^64
  std::size_t i = 0;
  bool negative = false;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) negative = t[i++] == '-';
  std::uint64_t m = 0;
  std::uint64_t den = 1;
  int digits = 0;
  bool point = false;
  for (; i < t.size(); ++i) {
    const char c = t[i];
    if (c == '.' && !point) {
      point = true;
      continue;
    }
    if (!is_digit(c) || ++digits > kMaxDigits) return false;
    m = m * 10 + static_cast<std::uint64_t>(c - '0');
    if (point) den *= 10;
  }
  if (digits == 0) return false;
  const std::uint64_t g = std::gcd(m, den); // m = 0: g = den, 0/1
  mpz_set_ui(out.get_num_mpz_t(), static_cast<unsigned long>(m / g));
  mpz_set_ui(out.get_den_mpz_t(), static_cast<unsigned long>(den / g));
  if (negative) mpz_neg(out.get_num_mpz_t(), out.get_num_mpz_t());
  return true;
}

// "[+-]digits/digits", the denominator non-zero.
bool try_parse_fraction(std::string_view t, std::size_t slash, Rational& out) {
  std::string_view num = t.substr(0, slash);
  const std::string_view den = t.substr(slash + 1);
  bool negative = false;
  if (!num.empty() && (num[0] == '+' || num[0] == '-')) {
    negative = num[0] == '-';
    num.remove_prefix(1);
  }
  if (num.empty() || den.empty() || !std::all_of(num.begin(), num.end(), is_digit) ||
      !std::all_of(den.begin(), den.end(), is_digit)) {
    return false;
  }
  const mpz_class n(std::string(num), 10);
  const mpz_class d(std::string(den), 10);
  if (d == 0) return false;
  out = Rational(negative ? mpz_class(-n) : n, d);
  out.canonicalize();
  return true;
}

// An exponent "e[+-]digits" from t[i] on (i just past the 'e'), added to `scale` (value =
// digits · 10^(-scale)); false past kMaxExponent or without digits.
bool read_exponent(std::string_view t, std::size_t& i, long& scale) {
  bool exp_negative = false;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) exp_negative = t[i++] == '-';
  if (i == t.size()) return false;
  long e = 0;
  while (i < t.size() && is_digit(t[i])) {
    e = e * 10 + (t[i++] - '0');
    if (e > kMaxExponent) return false;
  }
  scale += exp_negative ? e : -e;
  return true;
}

// "[+-]digits[.digits][e[+-]digits]", exactly, however many digits.
bool try_parse_decimal(std::string_view t, Rational& out) {
  std::size_t i = 0;
  bool negative = false;
  if (t[i] == '+' || t[i] == '-') negative = t[i++] == '-';
  std::string digits;
  long scale = 0; // value = digits · 10^(-scale)
  bool any = false;
  while (i < t.size() && is_digit(t[i])) {
    digits += t[i++];
    any = true;
  }
  if (i < t.size() && t[i] == '.') {
    ++i;
    while (i < t.size() && is_digit(t[i])) {
      digits += t[i++];
      ++scale;
      any = true;
    }
  }
  if (!any) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E') && !read_exponent(t, ++i, scale)) return false;
  if (i != t.size()) return false;
  mpz_class n(digits, 10);
  if (negative) n = -n;
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
  out = scale >= 0 ? Rational(n, p) : Rational(n * p);
  out.canonicalize();
  return true;
}

// Returns nullopt-like false on malformed text instead of throwing, so callers add context.
bool try_parse_rational(std::string_view t, Rational& out) {
  if (t.empty()) return false;
  if (try_parse_plain_decimal(t, out)) return true;
  if (const auto slash = t.find('/'); slash != std::string_view::npos) {
    return try_parse_fraction(t, slash, out);
  }
  return try_parse_decimal(t, out);
}

// Exact point-in-ring test (crossing number); the point is assumed off the ring's boundary.
bool point_in_ring(const Ring& ring, const ExactPoint& p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const ExactPoint& a = ring[i];
    const ExactPoint& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const Rational cross = (a.x - b.x) * (p.y - b.y) - (a.y - b.y) * (p.x - b.x);
      if ((b.y < a.y) ? sgn(cross) > 0 : sgn(cross) < 0) in = !in;
    }
  }
  return in;
}

// A new last vertex (0, 0), to be set in place: mpq_class's move is not noexcept, so std::vector
// would copy every point at each reallocation, and even a move allocates (gmpxx re-initialises
// the moved-from rational, which allocates its denominator): callers reserve what they know
// first, and the ring grows by moves only when they could not.
ExactPoint& append_point(Ring& ring) {
  if (ring.size() == ring.capacity()) {
    Ring grown;
    grown.reserve(std::max<std::size_t>(16, 2 * ring.size()));
    for (ExactPoint& v : ring) grown.push_back(std::move(v));
    ring.swap(grown);
  }
  return ring.emplace_back();
}

// Lines from `pos` up to the next blank one (or the end): at least the vertices of the x-y ring
// starting there, so it is reserved once (one pass over its bytes).
std::size_t lines_until_blank(std::string_view text, std::size_t pos) {
  std::size_t lines = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const auto blank = std::all_of(text.begin() + static_cast<std::ptrdiff_t>(pos),
                                   text.begin() + static_cast<std::ptrdiff_t>(end),
                                   [](char c) { return is_space(c); });
    if (blank) break;
    ++lines;
    pos = end + 1;
  }
  return lines;
}

void drop_closing_repeat(Ring& ring) {
  if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
}

// Assigns rings to polygons by nesting depth (even: outer, odd: hole of the nearest outer).
PolygonSet assemble_by_nesting(std::vector<Ring> rings) {
  const std::size_t n = rings.size();
  std::vector<std::size_t> depth(n, 0);
  std::vector<std::vector<std::size_t>> containers(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i != j && rings[j].size() >= 3 && !rings[i].empty() &&
          point_in_ring(rings[j], rings[i].front())) {
        containers[i].push_back(j);
        ++depth[i];
      }
    }
  }
  PolygonSet set;
  std::vector<std::size_t> polygon_of(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (depth[i] % 2 == 0) {
      polygon_of[i] = set.polygons.size();
      set.polygons.push_back({std::move(rings[i]), {}});
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (depth[i] % 2 == 1) {
      // The parent is the container one level up. Rings that contain each other (they touch
      // or overlap: invalid, and said so by validation) may leave none: the ring stands alone.
      std::optional<std::size_t> parent;
      for (std::size_t c : containers[i]) {
        if (depth[c] + 1 == depth[i]) parent = c;
      }
      if (parent) {
        set.polygons[polygon_of[*parent]].holes.push_back(std::move(rings[i]));
      } else {
        set.polygons.push_back({std::move(rings[i]), {}});
      }
    }
  }
  normalize_orientation(set);
  return set;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// The whitespace-separated fields of a line: how many, and the first two (no allocation: an x-y
// file has one line per vertex).
std::size_t first_two_fields(std::string_view s, std::array<std::string_view, 2>& first) {
  std::size_t count = 0;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && is_space(s[i])) ++i;
    const std::size_t start = i;
    while (i < s.size() && !is_space(s[i])) ++i;
    if (i > start) {
      if (count < first.size()) first[count] = s.substr(start, i - start);
      ++count;
    }
  }
  return count;
}

// WKT tokens: words, numbers, '(', ')', ','.
struct Token {
  std::string text;
  std::size_t line = 1;
};

std::vector<Token> wkt_tokens(std::string_view text) {
  std::vector<Token> out;
  std::size_t line = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (is_space(c)) {
      ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (c == '(' || c == ')' || c == ',') {
      out.push_back({std::string(1, c), line});
      ++i;
    } else {
      const std::size_t start = i;
      while (i < text.size() && !is_space(text[i]) && text[i] != '(' && text[i] != ')' &&
             text[i] != ',') {
        ++i;
      }
      out.push_back({std::string(text.substr(start, i - start)), line});
    }
  }
  return out;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

class WktParser {
 public:
  explicit WktParser(std::string_view text) : tokens_(wkt_tokens(text)) {}

  PolygonSet parse() {
    PolygonSet set;
    const std::string kind = upper(next("POLYGON or MULTIPOLYGON").text);
    if (kind != "POLYGON" && kind != "MULTIPOLYGON") {
      fail("expected POLYGON or MULTIPOLYGON, got '" + tokens_[pos_ - 1].text + "'");
    }
    if (peek_word() == "Z" || peek_word() == "M" || peek_word() == "ZM") {
      fail("Z/M coordinates are not supported");
    }
    if (peek_word() == "EMPTY") {
      ++pos_;
    } else if (kind == "POLYGON") {
      set.polygons.push_back(polygon());
    } else {
      expect("(");
      do {
        set.polygons.push_back(polygon());
      } while (accept(","));
      expect(")");
    }
    if (pos_ < tokens_.size()) fail("unexpected '" + tokens_[pos_].text + "' after the geometry");
    normalize_orientation(set);
    return set;
  }

 private:
  PolygonWithHoles polygon() {
    PolygonWithHoles p;
    expect("(");
    p.outer = ring();
    while (accept(",")) p.holes.push_back(ring());
    expect(")");
    return p;
  }

  Ring ring() {
    Ring r;
    expect("(");
    do {
      const Token& x = next("an x coordinate");
      const Token& y = next("a y coordinate");
      ExactPoint& p = append_point(r);
      p.x = number(x); // moved in by a swap
      p.y = number(y);
    } while (accept(","));
    expect(")");
    drop_closing_repeat(r);
    return r;
  }

  Rational number(const Token& t) {
    Rational v;
    if (!try_parse_rational(t.text, v))
      throw ParseError(t.line, "'" + t.text + "' is not a number");
    return v;
  }

  std::string peek_word() const { return pos_ < tokens_.size() ? upper(tokens_[pos_].text) : ""; }

  const Token& next(const std::string& what) {
    if (pos_ >= tokens_.size()) fail("the text ends where " + what + " was expected");
    return tokens_[pos_++];
  }

  bool accept(const char* s) {
    if (pos_ < tokens_.size() && tokens_[pos_].text == s) {
      ++pos_;
      return true;
    }
    return false;
  }

  void expect(const char* s) {
    const Token& t = next(std::string("'") + s + "'");
    if (t.text != s)
      throw ParseError(t.line, std::string("expected '") + s + "', got '" + t.text + "'");
  }

  [[noreturn]] void fail(const std::string& what) const {
    const std::size_t line = tokens_.empty() ? 1 : tokens_[std::min(pos_, tokens_.size() - 1)].line;
    throw ParseError(line, what);
  }

  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
};

std::string decimal_text(const Rational& v) {
  // Terminating when the denominator is 2^a·5^b: scale by 10^max(a, b).
  mpz_class den = v.get_den();
  unsigned long twos = mpz_remove(den.get_mpz_t(), den.get_mpz_t(), mpz_class(2).get_mpz_t());
  unsigned long fives = mpz_remove(den.get_mpz_t(), den.get_mpz_t(), mpz_class(5).get_mpz_t());
  if (den != 1) return v.get_str();
  const unsigned long k = std::max(twos, fives);
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 10, k);
  const mpz_class scaled = v.get_num() * p / v.get_den();
  std::string digits = mpz_class(abs(scaled)).get_str();
  std::string out = sgn(scaled) < 0 ? "-" : "";
  if (k == 0) return out.append(digits);
  if (digits.size() <= k) digits = std::string(k + 1 - digits.size(), '0').append(digits);
  const std::size_t point = digits.size() - k;
  out.append(digits, 0, point);
  out.push_back('.');
  out.append(digits, point, std::string::npos);
  return out;
}

void ring_wkt(std::string& out, const Ring& ring) {
  out += '(';
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const ExactPoint& p = ring[i % ring.size()];
    if (i) out += ", ";
    out += decimal_text(p.x) + " " + decimal_text(p.y);
  }
  out += ')';
}

} // namespace

Rational parse_rational(std::string_view text) {
  Rational v;
  if (!try_parse_rational(trim(text), v)) {
    throw InvalidInput("'" + std::string(text) + "' is not a number");
  }
  return v;
}

PolygonSet read_xy(std::string_view text) {
  std::vector<Ring> rings;
  Ring current;
  std::size_t line_number = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t line_start = pos;
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (line_number == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3); // BOM
    line = trim(line);
    if (!line.empty() && line.front() == '#') continue;
    if (line.empty()) {
      if (!current.empty()) {
        drop_closing_repeat(current);
        rings.push_back(std::move(current));
        current.clear();
      }
      continue;
    }
    if (current.empty()) current.reserve(lines_until_blank(text, line_start));
    std::array<std::string_view, 2> fields;
    const std::size_t field_count = first_two_fields(line, fields);
    if (field_count != 2) {
      throw ParseError(line_number, "expected two numbers 'x y', got " +
                                        std::to_string(field_count) + " fields");
    }
    ExactPoint& p = append_point(current); // read in place: no point is moved
    if (!try_parse_rational(fields[0], p.x)) {
      throw ParseError(line_number, "'" + std::string(fields[0]) + "' is not a number");
    }
    if (!try_parse_rational(fields[1], p.y)) {
      throw ParseError(line_number, "'" + std::string(fields[1]) + "' is not a number");
    }
  }
  if (!current.empty()) {
    drop_closing_repeat(current);
    rings.push_back(std::move(current));
  }
  if (rings.empty()) throw ParseError(line_number, "no vertices in the file");
  return assemble_by_nesting(std::move(rings));
}

PolygonSet read_wkt(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3); // UTF-8 byte order mark
  return WktParser(text).parse();
}

PolygonSet read_polygon_text(std::string_view text) {
  const auto tokens = wkt_tokens(text.substr(0, std::min<std::size_t>(text.size(), 1 << 16)));
  if (!tokens.empty()) {
    std::string first = upper(tokens.front().text);
    if (first.size() >= 3 && first.substr(0, 3) == "\xEF\xBB\xBF") first.erase(0, 3);
    if (first == "POLYGON" || first == "MULTIPOLYGON") return read_wkt(text);
  }
  return read_xy(text);
}

std::string to_wkt(const PolygonSet& set) {
  if (set.empty()) return "MULTIPOLYGON EMPTY";
  std::string out = "MULTIPOLYGON (";
  for (std::size_t i = 0; i < set.polygons.size(); ++i) {
    if (i) out += ", ";
    out += '(';
    ring_wkt(out, set.polygons[i].outer);
    for (const auto& h : set.polygons[i].holes) {
      out += ", ";
      ring_wkt(out, h);
    }
    out += ')';
  }
  out += ')';
  return out;
}

} // namespace penshape
