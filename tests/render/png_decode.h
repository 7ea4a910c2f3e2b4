// Decoding PNG bytes in tests, through cairo's PNG reader (an independent decoder from ours).
#pragma once

#include <cstdint>
#include <vector>

namespace vibro::testing {

struct Decoded {
  int width = 0;
  int height = 0;
  std::vector<std::uint32_t> argb;  // 0xAARRGGBB, premultiplied, row-major; empty on failure

  std::uint32_t at(int x, int y) const { return argb[static_cast<std::size_t>(y) * width + x]; }
};

Decoded decode_png(const std::vector<std::uint8_t>& bytes);

// Whether the pixel's colour is within `tolerance` per channel of 0xRRGGBB.
bool near_colour(std::uint32_t argb, std::uint32_t rgb, int tolerance);

}  // namespace vibro::testing
