#include "png_decode.h"

#include <cairo.h>

#include <cstdlib>
#include <cstring>

namespace vibro::testing {
namespace {

struct Reader {
  const std::vector<std::uint8_t>* bytes;
  std::size_t offset = 0;
};

cairo_status_t read_bytes(void* closure, unsigned char* data, unsigned int length) {
  auto* r = static_cast<Reader*>(closure);
  if (r->offset + length > r->bytes->size()) return CAIRO_STATUS_READ_ERROR;
  std::memcpy(data, r->bytes->data() + r->offset, length);
  r->offset += length;
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

Decoded decode_png(const std::vector<std::uint8_t>& bytes) {
  Reader reader{&bytes};
  cairo_surface_t* s = cairo_image_surface_create_from_png_stream(read_bytes, &reader);
  Decoded out;
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
    out.width = cairo_image_surface_get_width(s);
    out.height = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    const bool opaque = cairo_image_surface_get_format(s) == CAIRO_FORMAT_RGB24;
    out.argb.resize(static_cast<std::size_t>(out.width) * out.height);
    for (int y = 0; y < out.height; ++y) {
      std::memcpy(&out.argb[static_cast<std::size_t>(y) * out.width], data + y * stride,
                  4 * static_cast<std::size_t>(out.width));
      if (opaque)
        for (int x = 0; x < out.width; ++x)
          out.argb[static_cast<std::size_t>(y) * out.width + x] |= 0xFF000000u;
    }
  }
  cairo_surface_destroy(s);
  return out;
}

bool near_colour(std::uint32_t argb, std::uint32_t rgb, int tolerance) {
  for (int shift : {16, 8, 0}) {
    const int a = static_cast<int>((argb >> shift) & 0xff),
              b = static_cast<int>((rgb >> shift) & 0xff);
    if (std::abs(a - b) > tolerance) return false;
  }
  return true;
}

}  // namespace vibro::testing
