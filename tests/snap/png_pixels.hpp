#pragma once
// A PNG read into RGB pixels over white (libpng's simplified API), for checking what the apps
// rendered.
#include <png.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace penshape::test {

struct Pixels {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  // Darkness of the pixel at (x, y) in [0, 255] (255 - mean of r, g, b; outside: 0).
  [[nodiscard]] int ink(double x, double y) const {
    const int ix = static_cast<int>(x), iy = static_cast<int>(y);
    if (ix < 0 || iy < 0 || ix >= width || iy >= height) return 0;
    const std::uint8_t* p = &rgb[(static_cast<std::size_t>(iy) * static_cast<std::size_t>(width) +
                                  static_cast<std::size_t>(ix)) *
                                 3];
    return 255 - (p[0] + p[1] + p[2]) / 3;
  }
};

inline Pixels read_png(const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&image, path.c_str()) == 0) {
    throw std::runtime_error("cannot read PNG " + path + ": " + image.message);
  }
  image.format = PNG_FORMAT_RGB; // alpha composed over the white background below
  Pixels px;
  px.width = static_cast<int>(image.width);
  px.height = static_cast<int>(image.height);
  px.rgb.resize(PNG_IMAGE_SIZE(image));
  png_color white{255, 255, 255};
  if (png_image_finish_read(&image, &white, px.rgb.data(), 0, nullptr) == 0) {
    throw std::runtime_error("cannot decode PNG " + path + ": " + image.message);
  }
  return px;
}

} // namespace penshape::test
