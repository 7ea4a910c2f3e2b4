#include "render/gl/downsample.h"

#include <vector>

namespace vibro::gl {

void downsample_tile(std::span<const std::uint8_t> tile, int tile_width, int tile_height,
                     int factor, int x, int y, Image* out) {
  const int w = tile_width / factor;
  const int h = tile_height / factor;
  const int samples = factor * factor;
  std::vector<int> sums(static_cast<std::size_t>(w) * 3);
  for (int row = 0; row < h; ++row) {
    std::fill(sums.begin(), sums.end(), 0);
    // Output rows run top to bottom, GL's bottom to top.
    const int gl_row = (h - 1 - row) * factor;
    for (int k = 0; k < factor; ++k) {
      const std::uint8_t* src = tile.data() + static_cast<std::size_t>(gl_row + k) * tile_width * 4;
      for (int col = 0; col < w; ++col) {
        for (int j = 0; j < factor; ++j) {
          const std::uint8_t* p = src + (static_cast<std::size_t>(col) * factor + j) * 4;
          sums[3 * col] += p[0];
          sums[3 * col + 1] += p[1];
          sums[3 * col + 2] += p[2];
        }
      }
    }
    std::uint8_t* dst = out->rgba.data() + (static_cast<std::size_t>(y + row) * out->width + x) * 4;
    for (int col = 0; col < w; ++col) {
      for (int c = 0; c < 3; ++c) {
        dst[4 * col + c] = static_cast<std::uint8_t>((sums[3 * col + c] + samples / 2) / samples);
      }
      dst[4 * col + 3] = 255;
    }
  }
}

}  // namespace vibro::gl
