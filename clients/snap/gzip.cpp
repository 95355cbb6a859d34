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

std::string gunzip(std::string_view bytes, std::size_t limit) {
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) throw std::runtime_error("zlib: inflateInit2 failed");
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  std::string out;
  char buf[1 << 16];
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    z.next_out = reinterpret_cast<Bytef*>(buf);
    z.avail_out = sizeof buf;
    rc = inflate(&z, Z_NO_FLUSH);
    if (rc != Z_OK && rc != Z_STREAM_END) {
      const std::string why = z.msg != nullptr ? z.msg : "truncated";
      inflateEnd(&z);
      throw SnapInputError("gzip stream is corrupt at byte " + std::to_string(z.total_in) + ": " +
                           why);
    }
    const std::size_t n = sizeof buf - z.avail_out;
    if (out.size() + n > limit) {
      inflateEnd(&z);
      throw SnapInputError("gzip stream expands beyond " + std::to_string(limit) + " bytes");
    }
    // Grown by doubling, but never past the limit: a bomb never holds twice the limit.
    if (out.capacity() < out.size() + n) {
      out.reserve(std::min(std::max(2 * out.capacity(), out.size() + n), limit));
    }
    out.append(buf, n);
    if (rc == Z_OK && z.avail_in == 0 && z.avail_out != 0) {
      inflateEnd(&z);
      throw SnapInputError("gzip stream is truncated after " + std::to_string(out.size()) +
                           " bytes");
    }
  }
  inflateEnd(&z);
  return out;
}

std::string gzip(std::string_view bytes) {
  z_stream z{};
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
    throw std::runtime_error("zlib: deflateInit2 failed");
  }
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  std::string out;
  char buf[1 << 16];
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    z.next_out = reinterpret_cast<Bytef*>(buf);
    z.avail_out = sizeof buf;
    rc = deflate(&z, Z_FINISH);
    if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR) {
      deflateEnd(&z);
      throw std::runtime_error("zlib: deflate failed");
    }
    out.append(buf, sizeof buf - z.avail_out);
  }
  deflateEnd(&z);
  return out;
}

} // namespace penshape::snap
