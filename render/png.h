// PNG encoding in memory with libpng at a low zlib level: a figure is mostly flat colour, so the
// fast level compresses it nearly as well as the default one, in a fraction of the time.
#pragma once

#include <cstdint>
#include <vector>

#include "render/image.h"

namespace vibro::render {

// PNG bytes of an RGBA8 image (straight alpha). Empty on failure (out of memory, bad size).
std::vector<std::uint8_t> encode_png(const Image& image);

// PNG bytes of cairo image-surface pixels: 32-bit native-endian words 0xAARRGGBB, `stride` bytes
// per row. With `opaque` (CAIRO_FORMAT_RGB24) the alpha byte is ignored and the PNG is RGB;
// otherwise (CAIRO_FORMAT_ARGB32) colour is premultiplied and is divided out into RGBA.
std::vector<std::uint8_t> encode_png_argb32(const std::uint8_t* data, int width, int height,
                                            int stride, bool opaque);

}  // namespace vibro::render
