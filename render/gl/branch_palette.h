// Branch colours: the Okabe–Ito palette, which stays distinguishable under the common
// colour-vision deficiencies. Its yellow is left out (too faint on white) and its black is
// kept for the limiters.
#pragma once

#include <array>

#include "render/gl/mesh.h"

namespace vibro::gl {

inline constexpr std::array<Rgb8, 6> kBranchPalette = {{
    {0x00, 0x72, 0xB2},  // blue
    {0xD5, 0x5E, 0x00},  // vermillion
    {0x00, 0x9E, 0x73},  // bluish green
    {0xCC, 0x79, 0xA7},  // reddish purple
    {0xE6, 0x9F, 0x00},  // orange
    {0x56, 0xB4, 0xE9},  // sky blue
}};

// The colour of branch `index`, cycling through the palette; negative indices cycle too.
constexpr Rgb8 branch_colour(int index) {
  const int n = static_cast<int>(kBranchPalette.size());
  return kBranchPalette[((index % n) + n) % n];
}

}  // namespace vibro::gl
