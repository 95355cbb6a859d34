// The project-made documents of snap_documents.hpp.
#include "snap_documents.hpp"

#include <zip.h>
#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace penshape::test::docs {

std::vector<PointD> wobbly_circle(double cx, double cy, double r, int n) {
  std::vector<PointD> out;
  for (int i = 0; i <= n; ++i) {
    const double t = 2 * M_PI * i / n, rr = r * (1 + 0.01 * std::sin(5 * t));
    out.push_back({cx + rr * std::cos(t), cy - rr * std::sin(t)});
  }
  return out;
}

std::vector<PointD> wobbly_line(PointD a, PointD b, int n) {
  std::vector<PointD> out;
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const PointD normal{-(b.y - a.y) / len, (b.x - a.x) / len};
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / (n - 1), w = 0.3 * std::sin(7 * t);
    out.push_back({a.x + t * (b.x - a.x) + w * normal.x, a.y + t * (b.y - a.y) + w * normal.y});
  }
  return out;
}

std::string coordinates(const std::vector<PointD>& pts, const char* within) {
  std::string out;
  char buf[64];
  for (const PointD& p : pts) {
    std::snprintf(buf, sizeof buf, "%s%.3f%s%.3f", out.empty() ? "" : " ", p.x, within, p.y);
    out += buf;
  }
  return out;
}

std::string svg_document(const std::string& body) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         "<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" "
         "xmlns:sodipodi=\"http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd\" width=\"400\" "
         "height=\"300\" viewBox=\"0 0 400 300\">\n"
         "<defs><marker id=\"arrow\" orient=\"auto\" markerWidth=\"6\" markerHeight=\"6\" "
         "refX=\"3\" refY=\"3\"><path d=\"M0,0 L6,3 L0,6 z\" fill=\"#c00\"/></marker></defs>\n" +
         body + "</svg>\n";
}

std::string xopp_document(const std::vector<std::string>& layers) {
  std::string out =
      "<?xml version=\"1.0\" standalone=\"no\"?>\n<xournal creator=\"xournalpp "
      "1.1.3\" fileversion=\"4\">\n<title>Xournal++ document - see "
      "https://github.com/xournalpp/xournalpp</title>\n";
  for (const std::string& layer : layers) {
    out +=
        "<page width=\"400.00000000\" height=\"300.00000000\">\n<background type=\"solid\" "
        "color=\"#ffffffff\" style=\"plain\"/>\n<layer>\n" +
        layer + "</layer>\n</page>\n";
  }
  return out + "</xournal>\n";
}

std::string xopp_stroke(const std::vector<PointD>& pts, const std::string& width,
                        const std::string& color) {
  return "<stroke tool=\"pen\" color=\"" + color + "\" width=\"" + width +
         "\" capStyle=\"round\">" + coordinates(pts) + "</stroke>\n";
}

std::string zip_package(const std::vector<std::pair<std::string, std::string>>& entries) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* target = zip_source_buffer_create(nullptr, 0, 0, &error);
  zip_source_keep(target);
  zip_t* z = zip_open_from_source(target, ZIP_TRUNCATE, &error);
  if (z == nullptr) throw std::runtime_error("zip_open_from_source");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto& [name, bytes] = entries[i];
    zip_source_t* s = zip_source_buffer(z, bytes.data(), bytes.size(), 0);
    const zip_int64_t at = zip_file_add(z, name.c_str(), s, ZIP_FL_ENC_UTF_8);
    if (at < 0) throw std::runtime_error("zip_file_add " + name);
    if (i == 0) zip_set_file_compression(z, static_cast<zip_uint64_t>(at), ZIP_CM_STORE, 0);
  }
  if (zip_close(z) != 0) throw std::runtime_error("zip_close");
  zip_source_open(target);
  std::string out;
  char buf[4096];
  for (zip_int64_t n = zip_source_read(target, buf, sizeof buf); n > 0;
       n = zip_source_read(target, buf, sizeof buf)) {
    out.append(buf, static_cast<std::size_t>(n));
  }
  zip_source_close(target);
  zip_source_free(target);
  zip_error_fini(&error);
  return out;
}

std::map<std::string, std::string> zip_entries(const std::string& zip) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* source = zip_source_buffer_create(zip.data(), zip.size(), 0, &error);
  zip_t* z = zip_open_from_source(source, ZIP_RDONLY, &error);
  zip_error_fini(&error);
  if (z == nullptr) {
    zip_source_free(source);
    throw std::runtime_error("not a zip");
  }
  std::map<std::string, std::string> out;
  for (zip_int64_t i = 0; i < zip_get_num_entries(z, 0); ++i) {
    const auto index = static_cast<zip_uint64_t>(i);
    zip_file_t* f = zip_fopen_index(z, index, 0);
    std::string bytes;
    char buf[4096];
    for (zip_int64_t n = zip_fread(f, buf, sizeof buf); n > 0; n = zip_fread(f, buf, sizeof buf)) {
      bytes.append(buf, static_cast<std::size_t>(n));
    }
    zip_fclose(f);
    out[zip_get_name(z, index, 0)] = bytes;
  }
  zip_discard(z);
  return out;
}

std::string gzip_of_zeros(std::size_t bytes) {
  z_stream z{};
  deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY);
  const std::string zeros(1 << 20, '\0');
  std::string out;
  char buf[1 << 16];
  for (std::size_t left = bytes; left > 0 || z.avail_in > 0;) {
    const std::size_t slice = std::min(left, zeros.size());
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(zeros.data()));
    z.avail_in = static_cast<uInt>(slice);
    left -= slice;
    const int flush = left == 0 ? Z_FINISH : Z_NO_FLUSH;
    int rc = Z_OK;
    do {
      z.next_out = reinterpret_cast<Bytef*>(buf);
      z.avail_out = sizeof buf;
      rc = deflate(&z, flush);
      out.append(buf, sizeof buf - z.avail_out);
    } while (z.avail_out == 0 || (flush == Z_FINISH && rc != Z_STREAM_END));
    if (left == 0) break;
  }
  deflateEnd(&z);
  return out;
}

} // namespace penshape::test::docs
