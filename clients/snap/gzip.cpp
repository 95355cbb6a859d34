// zlib's inflate/deflate with gzip framing (windowBits 15 + 16; 15 + 32 detects the header).
#include "gzip.hpp"

#include <zlib.h>

#include <algorithm>
#include <stdexcept>

#include "snap_error.hpp"

namespace penshape::snap {

bool looks_gzipped(std::string_view b) {
  return b.size() >= 2 && static_cast<unsigned char>(b[0]) == 0x1f &&
         static_cast<unsigned char>(b[1]) == 0x8b;
}

namespace {

// One zlib stream (gzip framing), ended however the function that owns it is left.
class ZStream {
 public:
  explicit ZStream(bool inflating) : inflating_(inflating) {
    if (inflating) {
      if (inflateInit2(&z_, 15 + 32) != Z_OK) throw std::runtime_error("zlib: inflateInit2 failed");
    } else if (deflateInit2(&z_, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8,
                            Z_DEFAULT_STRATEGY) != Z_OK) {
      throw std::runtime_error("zlib: deflateInit2 failed");
    }
  }
  ~ZStream() { inflating_ ? inflateEnd(&z_) : deflateEnd(&z_); }
  ZStream(const ZStream&) = delete;
  ZStream& operator=(const ZStream&) = delete;

  // Inflates (or deflates to the end) `input` until the stream ends, handing each chunk of
  // output with zlib's code to `take`, which throws to stop.
  template <typename Take>
  void run(std::string_view input, Take take) {
    z_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(input.data()));
    z_.avail_in = static_cast<uInt>(input.size());
    char buf[1 << 16];
    int rc = Z_OK;
    while (rc != Z_STREAM_END) {
      z_.next_out = reinterpret_cast<Bytef*>(buf);
      z_.avail_out = sizeof buf;
      rc = inflating_ ? inflate(&z_, Z_NO_FLUSH) : deflate(&z_, Z_FINISH);
      take(std::string_view(buf, sizeof buf - z_.avail_out), rc);
    }
  }
  [[nodiscard]] const z_stream& state() const { return z_; }

 private:
  z_stream z_{};
  bool inflating_;
};

} // namespace

std::string gunzip(std::string_view bytes, std::size_t limit) {
  ZStream z(true);
  std::string out;
  z.run(bytes, [&](std::string_view chunk, int rc) {
    if (rc != Z_OK && rc != Z_STREAM_END) {
      const std::string why = z.state().msg != nullptr ? z.state().msg : "truncated";
      throw SnapInputError("gzip stream is corrupt at byte " + std::to_string(z.state().total_in) +
                           ": " + why);
    }
    if (out.size() + chunk.size() > limit) {
      throw SnapInputError("gzip stream expands beyond " + std::to_string(limit) + " bytes");
    }
    // Grown by doubling, but never past the limit: a bomb never holds twice the limit.
    if (out.capacity() < out.size() + chunk.size()) {
      out.reserve(std::min(std::max(2 * out.capacity(), out.size() + chunk.size()), limit));
    }
    out.append(chunk);
    if (rc == Z_OK && z.state().avail_in == 0 && z.state().avail_out != 0) {
      throw SnapInputError("gzip stream is truncated after " + std::to_string(out.size()) +
                           " bytes");
    }
  });
  return out;
}

std::string gzip(std::string_view bytes) {
  ZStream z(false);
  std::string out;
  z.run(bytes, [&](std::string_view chunk, int rc) {
    if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR) {
      throw std::runtime_error("zlib: deflate failed");
    }
    out.append(chunk);
  });
  return out;
}

} // namespace penshape::snap
