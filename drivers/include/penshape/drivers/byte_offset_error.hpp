#pragma once
// Malformed bytes and where they start: the base of the descriptor parser's and the recording
// reader's errors.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace penshape::drivers {

class ByteOffsetError : public std::runtime_error {
 public:
  // what() reads "<where> <offset>: <what>", e.g. "byte 12: bad hex".
  ByteOffsetError(const std::string& where, std::size_t offset, const std::string& what)
      : std::runtime_error(where + " " + std::to_string(offset) + ": " + what), offset_(offset) {}
  [[nodiscard]] std::size_t offset() const { return offset_; }

 private:
  std::size_t offset_;
};

} // namespace penshape::drivers
