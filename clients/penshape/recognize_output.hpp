#pragma once
// `penshape recognize`: the output rows (text or JSON), the SVG pictures and, with --labels,
// the confusion table.
#include <cstddef>
#include <map>
#include <string>

#include "recognize_options.hpp"
#include "recognize_work.hpp"

namespace penshape::cli {

class RecognizeReport {
 public:
  explicit RecognizeReport(const RecognizeOptions& options) : options_(options) {}

  // Prints one answer and writes its picture; throws std::runtime_error naming the SVG file it
  // cannot write.
  void add(const RecognizeRow& row);
  // With --labels: the confusion table (text) or the summary object (JSON).
  void finish() const;

 private:
  const RecognizeOptions& options_;
  std::map<std::string, std::map<std::string, std::size_t>> confusion_;
  std::size_t answers_ = 0;
  std::size_t correct_ = 0;
};

} // namespace penshape::cli
