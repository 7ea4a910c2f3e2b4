// Where the camera of the 3-D panel stands and what it frames.
#pragma once

#include "render/gl/view_math.h"
#include "render/plot_spec.h"

namespace vibro::gl {

// Nearest camera distance (cylinder radii): nearer ones would stand inside the scene.
inline constexpr double kMinCameraDistance = 1.8;

struct ViewSetup {
  Mat4 view;
  Mat4 projection;
  // Depth cueing: the scene fades towards the white background between these eye
  // distances, so the far side of the cylinder reads as behind the near side.
  float fog_start = 0.0f;
  float fog_end = 0.0f;
};

// The camera looks at the cylinder's centre from `camera.distance` radii (at least
// kMinCameraDistance), `azimuth_deg` anticlockwise from the φ = 0 direction and
// `elevation_deg` above the plane φ̇ = mid-range, with φ̇ up. The frustum is then fitted
// around the cylinder, its rims and floor ticks with a small margin, centred in a
// width × height panel: the scene is never cropped or lost in white space, and distance
// sets how strong the perspective is rather than a zoom.
ViewSetup cylinder_camera(const Camera& camera, int width, int height);

// Where a scene point lands in the view, as fractions of its width and height from the top
// left: where a label drawn over the image goes.
struct ViewFraction {
  double x = 0.0;
  double y = 0.0;
};
ViewFraction view_fraction(const ViewSetup& setup, Vec3 p);

}  // namespace vibro::gl
