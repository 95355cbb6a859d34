// Writers for generated strokes (see stroke_files.hpp).
#include "stroke_files.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace penshape::gen {
namespace {

std::string number_name(const std::string& kind, int number) {
  char digits[16];
  std::snprintf(digits, sizeof digits, "%02d", number);
  return kind + digits;
}

std::string fixed(double v, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

} // namespace

std::string to_dollar_xml(const GenStroke& stroke, const std::string& name, int subject,
                          Speed speed) {
  const auto ms = [](double t) { return std::llround(t * 1000.0); };
  const long long duration = stroke.points.empty() ? 0 : ms(stroke.points.back().t);
  std::string out = "<?xml version=\"1.0\" encoding=\"utf-8\" standalone=\"yes\"?>\n";
  out += "<Gesture Name=\"" + name + "\" Subject=\"" + std::to_string(subject) + "\" Speed=\"" +
         to_string(speed) + "\" NumPts=\"" + std::to_string(stroke.points.size()) +
         "\" Millseconds=\"" + std::to_string(duration) +
         "\" AppName=\"penshape stroke generator\">\n";
  for (const auto& p : stroke.points) {
    out += "  <Point X=\"" + std::to_string(std::llround(p.x)) + "\" Y=\"" +
           std::to_string(std::llround(p.y)) + "\" T=\"" + std::to_string(ms(p.t)) + "\" />\n";
  }
  return out + "</Gesture>\n";
}

std::string to_jsonl(const Drawing& drawing, const std::string& name) {
  std::string out;
  for (const auto& s : drawing.strokes) {
    std::string line =
        "{\"name\": \"" + name + "\", \"label\": \"" + drawing.kind + "\", \"points\": [";
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const auto& p = s.points[i];
      line += (i ? ", [" : "[") + fixed(p.x, 0) + ", " + fixed(p.y, 0) + ", " + fixed(p.t, 3) +
              ", " + fixed(s.pressure[i], 3) + "]";
    }
    out += line + "]}\n";
  }
  return out;
}

std::size_t write_dollar_corpus(const std::filesystem::path& dir,
                                const std::vector<CorpusEntry>& entries) {
  for (const auto& e : entries) {
    const auto folder = dir / number_name("s", e.subject) / to_string(e.speed);
    std::filesystem::create_directories(folder);
    const std::string name = number_name(e.drawing.kind, e.number);
    std::ofstream out(folder / (name + ".xml"), std::ios::binary);
    out << to_dollar_xml(e.drawing.strokes.front(), name, e.subject, e.speed);
    if (!out) throw std::runtime_error("cannot write " + (folder / name).string());
  }
  return entries.size();
}

} // namespace penshape::gen
