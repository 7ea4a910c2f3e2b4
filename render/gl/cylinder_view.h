// The 3-D panel: one pellet's trajectory on the phase cylinder (cos φ, sin φ, φ̇), drawn
// offscreen with OSMesa. Thread-safe: concurrent calls are served one at a time.
#pragma once

#include <string>

#include "render/gl/cylinder_scene.h"
#include "render/image.h"

namespace vibro::gl {

// Largest width or height of a cylinder view, in pixels.
inline constexpr int kMaxCylinderViewSide = 4096;

// Draws `scene` into a width × height opaque image on white, framed as cylinder_camera.h
// describes. On failure (size outside 1..kMaxCylinderViewSide, a camera with a non-finite
// angle or a non-positive distance, or OSMesa unavailable) returns an empty Image and sets
// *error when error is not null. Loads libOSMesa on the first call.
Image render_cylinder_view(const CylinderScene& scene, int width, int height, std::string* error);

}  // namespace vibro::gl
