#include "render/image_surface.h"

#include <cstdint>
#include <cstring>

namespace vibro::render {

SurfacePtr surface_from_image(const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    return nullptr;
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, image.width, image.height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) return nullptr;
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* src = image.rgba.data() + static_cast<std::size_t>(y) * image.width * 4;
    unsigned char* row = data + static_cast<std::size_t>(y) * stride;
    for (int x = 0; x < image.width; ++x) {
      const unsigned a = src[4 * x + 3];
      const auto pre = [a](unsigned c) { return (c * a + 127) / 255; };
      const std::uint32_t word =
          (a << 24) | (pre(src[4 * x]) << 16) | (pre(src[4 * x + 1]) << 8) | pre(src[4 * x + 2]);
      std::memcpy(row + 4 * x, &word, 4);
    }
  }
  cairo_surface_mark_dirty(surface.get());
  return surface;
}

}  // namespace vibro::render
