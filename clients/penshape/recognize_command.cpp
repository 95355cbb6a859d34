// `penshape recognize`: the certified recognizer on stroke files (formats in stroke_files.hpp),
// grouping the strokes of a JSON-lines file, with an optional confusion table against labels.
// Options: recognize_options.hpp; the work per file: recognize_work.hpp; the rows:
// recognize_output.hpp.
#include "recognize_command.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "command.hpp"
#include "penshape/render/progress_bar.hpp"
#include "recognize_options.hpp"
#include "recognize_output.hpp"
#include "recognize_work.hpp"
#include "stroke_files.hpp"

namespace penshape::cli {
namespace {

int bad_input(const std::string& message) {
  std::fprintf(stderr, "penshape recognize: %s\n", message.c_str());
  return kExitBadInput;
}

} // namespace

int run_recognize(std::span<const std::string_view> args) {
  const RecognizeOptions options = parse_recognize_options(args);
  if (options.help) {
    std::puts(kRecognizeHelp);
    return kExitOk;
  }
  if (options.svg_dir) {
    std::error_code ec;
    std::filesystem::create_directories(*options.svg_dir, ec);
    if (ec) return bad_input("cannot create '" + *options.svg_dir + "': " + ec.message());
  }
  std::vector<std::string> files;
  try {
    files = collect_stroke_files(options.inputs);
  } catch (const StrokeFileError& e) {
    return bad_input(e.what());
  }
  // Large directories: a progress bar on the terminal while the results go to a file or pipe
  // (drawn only on a TTY; never mixed into results printed on the same terminal).
  render::ProgressBar bar("recognize", files.size(), stderr,
                          ::isatty(STDOUT_FILENO) != 0 ? render::ProgressBar::Mode::kNever
                                                       : render::ProgressBar::Mode::kAuto);
  RecognizeReport report(options);
  for (const std::string& file : files) {
    bar.advance();
    try {
      const std::vector<FileStroke> batch = read_stroke_file(file);
      for (const RecognizeRow& row : recognize_batch(batch, options)) report.add(row);
    } catch (const StrokeFileError& e) {
      return bad_input(e.what());
    } catch (const std::runtime_error& e) { // an SVG file that cannot be written
      return bad_input(e.what());
    }
  }
  bar.finish();
  report.finish();
  return kExitOk;
}

} // namespace penshape::cli
