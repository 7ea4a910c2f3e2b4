// Antialiasing by supersampling: OSMesa has no multisampling, so panels are drawn at a
// multiple of their size and each block of samples is averaged into one pixel.
#pragma once

#include <cstdint>
#include <span>

#include "render/image.h"

namespace vibro::gl {

// Box-averages each factor × factor block of `tile` (RGBA8, tile_width × tile_height, rows
// bottom to top as GL reads them; both sizes multiples of factor) into `out`, with the
// tile's top-left block landing on pixel (x, y). The panel is opaque: alpha is set to 255.
void downsample_tile(std::span<const std::uint8_t> tile, int tile_width, int tile_height,
                     int factor, int x, int y, Image* out);

}  // namespace vibro::gl
