// $1 gesture-log XML and JSON-lines stroke readers (formats in stroke_files.hpp).
#include "stroke_files.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace penshape::cli {
namespace {

[[noreturn]] void fail(const std::string& file, std::size_t line, const std::string& what) {
  throw StrokeFileError(file + ":" + std::to_string(line) + ": " + what);
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::optional<double> parse_double(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '+')) s.remove_prefix(1);
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// Value of attribute `name` in an XML tag's text, if present.
std::optional<std::string> attribute(const std::string& tag, const std::string& name) {
  std::size_t pos = 0;
  while ((pos = tag.find(name, pos)) != std::string::npos) {
    const bool starts = pos > 0 && std::isspace(static_cast<unsigned char>(tag[pos - 1]));
    std::size_t q = pos + name.size();
    while (q < tag.size() && tag[q] == ' ') ++q;
    if (starts && q < tag.size() && tag[q] == '=') {
      ++q;
      while (q < tag.size() && tag[q] == ' ') ++q;
      if (q >= tag.size() || (tag[q] != '"' && tag[q] != '\'')) return std::nullopt;
      const char quote = tag[q];
      const std::size_t end = tag.find(quote, q + 1);
      if (end == std::string::npos) return std::nullopt;
      return tag.substr(q + 1, end - q - 1);
    }
    pos += name.size();
  }
  return std::nullopt;
}

std::vector<FileStroke> read_dollar_xml(const std::string& path, const std::string& text) {
  FileStroke stroke;
  stroke.file = path;
  bool in_gesture = false;
  bool closed = false;
  std::size_t line = 1;
  std::size_t pos = 0;
  std::size_t counted = 0; // newlines before `counted` are in `line`
  while ((pos = text.find('<', pos)) != std::string::npos) {
    line +=
        static_cast<std::size_t>(std::count(text.begin() + static_cast<std::ptrdiff_t>(counted),
                                            text.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
    counted = pos;
    const std::size_t end = text.find('>', pos);
    if (end == std::string::npos) fail(path, line, "unterminated XML tag");
    const std::string tag = text.substr(pos + 1, end - pos - 1);
    const std::size_t tag_line = line;
    pos = end + 1;
    if (tag.rfind("Gesture", 0) == 0) {
      if (in_gesture || closed) fail(path, tag_line, "more than one <Gesture> element");
      in_gesture = true;
      stroke.line = tag_line;
      stroke.name = attribute(tag, "Name").value_or("");
    } else if (tag.rfind("/Gesture", 0) == 0) {
      if (!in_gesture) fail(path, tag_line, "</Gesture> without <Gesture>");
      in_gesture = false;
      closed = true;
    } else if (tag.rfind("Point", 0) == 0) {
      if (!in_gesture) fail(path, tag_line, "<Point> outside <Gesture>");
      StrokePoint p;
      for (const char* key : {"X", "Y"}) {
        const std::optional<std::string> v = attribute(tag, key);
        if (!v) fail(path, tag_line, std::string("<Point> without attribute ") + key);
        const std::optional<double> d = parse_double(*v);
        if (!d)
          fail(path, tag_line,
               std::string("attribute ") + key + "=\"" + *v + "\" is not a finite number");
        (key[0] == 'X' ? p.x : p.y) = *d;
      }
      if (const std::optional<std::string> t = attribute(tag, "T")) {
        const std::optional<double> d = parse_double(*t);
        if (!d) fail(path, tag_line, "attribute T=\"" + *t + "\" is not a finite number");
        p.t = *d / 1000.0;
      }
      stroke.points.push_back(p);
    }
  }
  if (in_gesture) fail(path, line, "missing </Gesture> (truncated file?)");
  if (!closed) fail(path, line, "no <Gesture> element");
  return {stroke};
}

// A minimal strict JSON reader for the JSON-lines format.
class JsonLine {
 public:
  JsonLine(const std::string& file, std::size_t line, std::string_view text)
      : file_(file), line_(line), s_(text) {}

  FileStroke parse_stroke() {
    FileStroke out;
    out.file = file_;
    out.line = line_;
    bool have_points = false;
    expect('{');
    if (!peek('}')) {
      do {
        const std::string key = string();
        expect(':');
        if (key == "points") {
          out.pressure.clear();
          out.points = points(out.pressure);
          have_points = true;
        } else if (key == "name") {
          out.name = string();
        } else if (key == "label") {
          out.label = string();
        } else {
          skip_value();
        }
      } while (accept(','));
    }
    expect('}');
    ws();
    if (i_ != s_.size()) error("unexpected text after the stroke object");
    if (!have_points) error("the stroke object has no \"points\"");
    return out;
  }

 private:
  [[noreturn]] void error(const std::string& what) const {
    fail(file_, line_, what + " (column " + std::to_string(i_ + 1) + ")");
  }
  void ws() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool peek(char c) {
    ws();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  bool accept(char c) { return peek(c); }
  void expect(char c) {
    if (!peek(c)) error(std::string("expected '") + c + "'");
  }
  std::string string() {
    ws();
    if (i_ >= s_.size() || s_[i_] != '"') error("expected a string");
    ++i_;
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      if (s_[i_] == '\\') {
        if (++i_ >= s_.size()) break;
        const char e = s_[i_];
        out += e == 'n' ? '\n' : e == 't' ? '\t' : e; // \uXXXX kept verbatim-ish; names only
      } else {
        out += s_[i_];
      }
      ++i_;
    }
    if (i_ >= s_.size()) error("unterminated string");
    ++i_;
    return out;
  }
  double number() {
    ws();
    std::size_t j = i_;
    while (j < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[j])) || s_[j] == '-' ||
                             s_[j] == '+' || s_[j] == '.' || s_[j] == 'e' || s_[j] == 'E')) {
      ++j;
    }
    const std::optional<double> v = parse_double(s_.substr(i_, j - i_));
    if (j == i_ || !v) error("expected a finite number");
    i_ = j;
    return *v;
  }
  std::vector<StrokePoint> points(std::vector<double>& pressure) {
    std::vector<StrokePoint> out;
    expect('[');
    if (peek(']')) return out;
    do {
      expect('[');
      StrokePoint p;
      p.x = number();
      expect(',');
      p.y = number();
      bool pressed = false;
      if (accept(',')) {
        p.t = number();
        if (accept(',')) {
          const double v = number();
          if (v < 0 || v > 1) error("a pressure value is outside [0, 1]");
          pressure.push_back(v);
          pressed = true;
        }
      }
      if (pressed != (pressure.size() == out.size() + 1) || (!pressed && !pressure.empty())) {
        error("pressure must be given for every point or for none");
      }
      expect(']');
      out.push_back(p);
    } while (accept(','));
    expect(']');
    return out;
  }
  void skip_value() {
    ws();
    if (i_ >= s_.size()) error("expected a value");
    const char c = s_[i_];
    if (c == '"') {
      string();
    } else if (c == '{' || c == '[') {
      const char close = c == '{' ? '}' : ']';
      ++i_;
      if (peek(close)) return;
      do {
        if (c == '{') {
          string();
          expect(':');
        }
        skip_value();
      } while (accept(','));
      expect(close);
    } else if (s_.substr(i_, 4) == "true" || s_.substr(i_, 4) == "null") {
      i_ += 4;
    } else if (s_.substr(i_, 5) == "false") {
      i_ += 5;
    } else {
      number();
    }
  }

  const std::string& file_;
  std::size_t line_;
  std::string_view s_;
  std::size_t i_ = 0;
};

std::vector<FileStroke> read_json_lines(const std::string& path, const std::string& text) {
  std::vector<FileStroke> out;
  std::istringstream in(text);
  std::string row;
  std::size_t line = 0;
  while (std::getline(in, row)) {
    ++line;
    if (std::all_of(row.begin(), row.end(), [](unsigned char c) { return std::isspace(c); })) {
      continue;
    }
    out.push_back(JsonLine(path, line, row).parse_stroke());
  }
  return out;
}

} // namespace

std::vector<FileStroke> read_stroke_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, 0, "cannot open the file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  const std::string ext = lower_extension(path);
  if (ext == ".xml") return read_dollar_xml(path, text);
  if (ext == ".jsonl" || ext == ".ndjson") return read_json_lines(path, text);
  fail(path, 0, "unknown stroke file type (expected .xml, .jsonl or .ndjson)");
}

std::vector<std::string> collect_stroke_files(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (const std::string& a : args) {
    std::error_code ec;
    if (std::filesystem::is_directory(a, ec)) {
      std::vector<std::string> found;
      for (const auto& e : std::filesystem::recursive_directory_iterator(a, ec)) {
        if (!e.is_regular_file()) continue;
        const std::string ext = lower_extension(e.path().string());
        if (ext == ".xml" || ext == ".jsonl" || ext == ".ndjson")
          found.push_back(e.path().string());
      }
      if (ec) fail(a, 0, "cannot read the directory: " + ec.message());
      std::sort(found.begin(), found.end());
      out.insert(out.end(), found.begin(), found.end());
    } else if (std::filesystem::exists(a, ec)) {
      out.push_back(a);
    } else {
      fail(a, 0, "no such file or directory");
    }
  }
  return out;
}

} // namespace penshape::cli
