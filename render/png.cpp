#include "render/png.h"

#include <png.h>

#include <csetjmp>
#include <cstring>

namespace vibro::render {
namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}

void no_flush(png_structp) {}

// Converts row y of the source into 8-bit channels (RGB or RGBA) in `row`.
using RowFiller = void (*)(const void* source, int y, std::uint8_t* row);

// libpng reports errors by longjmp: this frame holds no object with a destructor, and the
// caller owns every buffer, so the jump skips nothing.
bool write_png(std::vector<std::uint8_t>* out, int width, int height, bool alpha,
               const void* source, RowFiller fill, std::uint8_t* row) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, out, append_bytes, no_flush);
  png_set_IHDR(png, info, width, height, 8, alpha ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // zlib's fastest level without row filters: on figures (flat background, thin lines) it is
  // the quickest choice measured and within 10% of the smallest; "sub" and "up" filters or the
  // RLE strategy cost more time for no smaller file.
  png_set_compression_level(png, 1);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y) {
    fill(source, y, row);
    png_write_row(png, row);
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

struct SurfacePixels {
  const std::uint8_t* data;
  int width;
  int stride;

  // The native-endian 0xAARRGGBB word at (x, y).
  std::uint32_t at(int x, int y) const {
    std::uint32_t word;
    std::memcpy(&word, data + static_cast<std::size_t>(y) * stride + 4 * x, 4);
    return word;
  }
};

void fill_rgb(const void* source, int y, std::uint8_t* row) {
  const auto& s = *static_cast<const SurfacePixels*>(source);
  for (int x = 0; x < s.width; ++x) {
    const std::uint32_t word = s.at(x, y);
    row[3 * x + 0] = static_cast<std::uint8_t>(word >> 16);
    row[3 * x + 1] = static_cast<std::uint8_t>(word >> 8);
    row[3 * x + 2] = static_cast<std::uint8_t>(word);
  }
}

void fill_unpremultiplied(const void* source, int y, std::uint8_t* row) {
  const auto& s = *static_cast<const SurfacePixels*>(source);
  for (int x = 0; x < s.width; ++x) {
    const std::uint32_t word = s.at(x, y);
    const unsigned a = word >> 24;
    const auto channel = [a](unsigned c) {
      return static_cast<std::uint8_t>(a == 0 ? 0 : (c * 255 + a / 2) / a);
    };
    row[4 * x + 0] = channel((word >> 16) & 0xff);
    row[4 * x + 1] = channel((word >> 8) & 0xff);
    row[4 * x + 2] = channel(word & 0xff);
    row[4 * x + 3] = static_cast<std::uint8_t>(a);
  }
}

void fill_rgba(const void* source, int y, std::uint8_t* row) {
  const auto& image = *static_cast<const Image*>(source);
  const std::size_t bytes = static_cast<std::size_t>(image.width) * 4;
  std::memcpy(row, image.rgba.data() + y * bytes, bytes);
}

bool valid_size(int width, int height) { return width > 0 && height > 0; }

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  if (!valid_size(image.width, image.height) ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    return {};
  std::vector<std::uint8_t> out;
  std::vector<std::uint8_t> row(static_cast<std::size_t>(image.width) * 4);
  if (!write_png(&out, image.width, image.height, true, &image, fill_rgba, row.data())) return {};
  return out;
}

std::vector<std::uint8_t> encode_png_argb32(const std::uint8_t* data, int width, int height,
                                            int stride, bool opaque) {
  if (!data || !valid_size(width, height) || stride < 4 * width) return {};
  const SurfacePixels pixels{data, width, stride};
  std::vector<std::uint8_t> out;
  std::vector<std::uint8_t> row(static_cast<std::size_t>(width) * 4);
  if (!write_png(&out, width, height, !opaque, &pixels, opaque ? fill_rgb : fill_unpremultiplied,
                 row.data()))
    return {};
  return out;
}

}  // namespace vibro::render
