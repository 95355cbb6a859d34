// libFuzzer: arbitrary bytes through every file reader of the CLI and the daemon's config. The
// first byte chooses the reader (polygon text: x-y or WKT; stroke file as JSON lines or as a $1
// XML log; penshaped config; the JSON answers `penshape verify` reads); the rest is the file. Each
// reader must return or throw its own documented error (which names the line); anything else, or a
// crash, is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "json_value.hpp"
#include "penshape/core/polygon_io.hpp"
#include "penshape/daemon/config.hpp"
#include "stroke_files.hpp"

namespace {

// The stroke readers take a path (the format follows the extension): the bytes go to a file of
// this process's own.
std::string write_temp(std::string_view bytes, const char* extension) {
  const std::string path =
      "/tmp/penshape-fuzz-" + std::to_string(::getpid()) + "-stroke" + extension;
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
  }
  return path;
}

void read_strokes(std::string_view bytes, const char* extension) {
  const std::string path = write_temp(bytes, extension);
  try {
    (void)penshape::cli::read_stroke_file(path);
  } catch (const penshape::cli::StrokeFileError&) {
  }
  std::remove(path.c_str());
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch (data[0] % 5) {
    case 0:
      try {
        (void)penshape::read_polygon_text(text);
      } catch (const penshape::InvalidInput&) {
      }
      break;
    case 1:
      read_strokes(text, ".jsonl");
      break;
    case 2:
      read_strokes(text, ".xml");
      break;
    case 4:
      try {
        (void)penshape::cli::parse_json_values(text);
      } catch (const penshape::cli::JsonError&) {
      }
      break;
    default:
      try {
        (void)penshape::daemon::parse_config(text, "fuzz.conf");
      } catch (const penshape::daemon::ConfigError&) {
      }
      break;
  }
  return 0;
}
