// PNG encoding in memory of cairo image surfaces, through our figure deflater
// (render/image_deflate.h): a figure is mostly flat colour and repeated rows.
#pragma once

#include <cstdint>
#include <vector>

namespace vibro::render {

// PNG bytes of cairo image-surface pixels: 32-bit native-endian words 0xAARRGGBB, `stride` bytes
// per row. With `opaque` (CAIRO_FORMAT_RGB24) the alpha byte is ignored and the PNG is RGB;
// otherwise (CAIRO_FORMAT_ARGB32) colour is premultiplied and is divided out into RGBA.
// Empty on bad input (no data, a size of zero, a stride shorter than a row). With `dpi` > 0 the
// PNG says its resolution (a pHYs chunk), so that it is placed at its print size.
std::vector<std::uint8_t> encode_png_argb32(const std::uint8_t* data, int width, int height,
                                            int stride, bool opaque, double dpi = 0.0);

}  // namespace vibro::render
