// Stroke files (formats in stroke_files.hpp): JSON lines through nlohmann-json, $1 gesture logs
// through dollar_xml.hpp.
#include "stroke_files.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "dollar_xml.hpp"

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

// A $1 gesture log, through the one reader (dollar_xml.hpp).
std::vector<FileStroke> read_dollar_xml(const std::string& path, const std::string& text) {
  dollar::Gesture g;
  try {
    g = dollar::parse_dollar_xml(text, path);
  } catch (const dollar::DollarXmlError& e) {
    throw StrokeFileError(e.what());
  }
  FileStroke stroke;
  stroke.file = path;
  stroke.line = g.line;
  stroke.name = std::move(g.name);
  stroke.points = std::move(g.points);
  return {stroke};
}

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
