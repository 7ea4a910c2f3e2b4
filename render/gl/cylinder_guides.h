// What makes the cylinder read as one: its translucent wall, the rims, the φ̇ = 0 level,
// φ ticks on the floor rim, the axis, and the limiter lines.
#pragma once

#include <vector>

#include "render/gl/cylinder_layout.h"
#include "render/gl/mesh.h"

namespace vibro::gl {

// The cylinder's side wall over the full height, outward normals, counter-clockwise front
// faces seen from outside; drawn translucent.
Mesh cylinder_wall();

// A line along the cylinder at each limiter angle (rad), over the full height.
LineSet limiter_lines(const std::vector<double>& angles);

// Rims, the dashed φ̇ = 0 ring when 0 is in range, the z axis, and φ ticks pointing out of
// the floor rim every 30° (longer every 90°, longest at φ = 0).
std::vector<LineSet> guide_lines(const HeightScale& scale);

}  // namespace vibro::gl
