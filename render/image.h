// An RGBA8 raster: straight (not premultiplied) alpha, rows top to bottom, 4 bytes per pixel.
#pragma once

#include <cstdint>
#include <vector>

namespace vibro {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4
};

}  // namespace vibro
