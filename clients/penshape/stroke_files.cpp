// $1 gesture-log XML and JSON-lines stroke readers (formats in stroke_files.hpp).
#include "stroke_files.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

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

// One point [x, y], [x, y, t] or [x, y, t, pressure] of the stroke on `line`.
StrokePoint json_point(const nlohmann::json& v, std::size_t index, FileStroke& out) {
  const std::string where = "\"points\"[" + std::to_string(index) + "]";
  if (!v.is_array() || v.size() < 2 || v.size() > 4) {
    fail(out.file, out.line, where + " must be an array of 2 to 4 numbers [x, y, t, pressure]");
  }
  double n[4] = {0, 0, 0, 0};
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (!v[k].is_number()) fail(out.file, out.line, where + " holds something other than a number");
    n[k] = v[k].get<double>();
    if (!std::isfinite(n[k]))
      fail(out.file, out.line, where + " holds a number that is not finite");
  }
  const bool timed = v.size() >= 3;
  if (index == 0) out.timed = timed;
  if (timed != out.timed) {
    fail(out.file, out.line, "t must be given for every point or for none (" + where + ")");
  }
  if (v.size() == 4) {
    if (n[3] < 0 || n[3] > 1)
      fail(out.file, out.line, where + ": a pressure value is outside [0, 1]");
    out.pressure.push_back(n[3]);
  }
  if (!out.pressure.empty() && out.pressure.size() != index + 1) {
    fail(out.file, out.line, "pressure must be given for every point or for none (" + where + ")");
  }
  return {n[0], n[1], n[2]};
}

// Times, when given, must increase strictly along a stroke.
void check_times(const FileStroke& s) {
  if (!s.timed) return;
  for (std::size_t i = 1; i < s.points.size(); ++i) {
    const double a = s.points[i - 1].t, b = s.points[i].t;
    if (b == a) {
      fail(s.file, s.line,
           "\"points\"[" + std::to_string(i) + "] has the same time t as the point before it");
    }
    if (b < a) {
      fail(s.file, s.line, "\"points\"[" + std::to_string(i) + "]: the time t goes backwards");
    }
  }
}

FileStroke json_stroke(const std::string& path, std::size_t line, const std::string& row) {
  FileStroke out;
  out.file = path;
  out.line = line;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(row);
  } catch (const nlohmann::json::exception& e) { // syntax, number overflow, bad UTF-8
    fail(path, line, std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_object()) fail(path, line, "a stroke must be a JSON object {\"points\": [...]}");
  const auto points = j.find("points");
  if (points == j.end()) fail(path, line, "the stroke object has no \"points\"");
  if (!points->is_array()) fail(path, line, "\"points\" must be an array");
  for (const char* key : {"name", "label"}) {
    const auto it = j.find(key);
    if (it == j.end()) continue;
    if (!it->is_string()) fail(path, line, std::string("\"") + key + "\" must be a string");
    (key[0] == 'n' ? out.name : out.label) = it->get<std::string>();
  }
  for (std::size_t i = 0; i < points->size(); ++i) {
    out.points.push_back(json_point((*points)[i], i, out));
  }
  if (out.points.empty()) fail(path, line, "the stroke has no points (a dot has one)");
  check_times(out);
  return out;
}

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
    out.push_back(json_stroke(path, line, row));
    // Strokes are in drawing order: with times, one cannot start before the previous ended.
    if (out.size() >= 2) {
      const FileStroke& a = out[out.size() - 2];
      const FileStroke& b = out.back();
      if (a.timed && b.timed && b.points.front().t < a.points.back().t) {
        fail(path, line, "the stroke starts (t) before the previous stroke ended");
      }
    }
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
