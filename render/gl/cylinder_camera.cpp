#include "render/gl/cylinder_camera.h"

#include <algorithm>
#include <numbers>
#include <vector>

#include "render/gl/cylinder_layout.h"

namespace vibro::gl {
namespace {

// Radius of the floor circle that holds the tips of the φ ticks.
constexpr double kTickReach = 1.16;
// Blank border around the framed scene, as a fraction of its size.
constexpr double kMargin = 0.08;

// Points whose hull holds everything drawn: the top rim and the floor tick circle. The
// scene is symmetric about its axis, so the framing does not change with azimuth.
std::vector<Vec3> framing_points() {
  std::vector<Vec3> points;
  constexpr int kSteps = 72;
  for (int i = 0; i < kSteps; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / kSteps;
    points.push_back(on_cylinder(phi, kHalfHeight));
    points.push_back(kTickReach * on_cylinder(phi, -kHalfHeight / kTickReach));
  }
  return points;
}

}  // namespace

ViewSetup cylinder_camera(const Camera& camera, int width, int height) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  const double az = camera.azimuth_deg * kDeg;
  // Straight down or up the axis leaves "up" undefined; stop just short of it.
  const double el = std::clamp(camera.elevation_deg, -89.0, 89.0) * kDeg;
  const double d = std::max(camera.distance, kMinCameraDistance);
  const Vec3 eye = d * Vec3{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
  const Mat4 view = look_at(eye, {}, {0.0, 0.0, 1.0});

  // Bounds of the scene as seen from the eye, on the plane one unit in front of it.
  double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;
  for (const Vec3& p : framing_points()) {
    const Vec3 e = transform_point(view, p);
    left = std::min(left, -e.x / e.z);
    right = std::max(right, -e.x / e.z);
    bottom = std::min(bottom, -e.y / e.z);
    top = std::max(top, -e.y / e.z);
  }
  // Centre the bounds, pad them, and widen the short way to the panel's aspect.
  const double cx = 0.5 * (left + right), cy = 0.5 * (bottom + top);
  double hx = 0.5 * (right - left) * (1.0 + kMargin);
  double hy = 0.5 * (top - bottom) * (1.0 + kMargin);
  const double aspect = static_cast<double>(width) / height;
  if (hx < hy * aspect) {
    hx = hy * aspect;
  } else {
    hy = hx / aspect;
  }
  const double reach = std::hypot(kTickReach, kHalfHeight);  // the scene's bounding sphere
  const double near = d - reach, far = d + reach;
  return {
      view,
      frustum((cx - hx) * near, (cx + hx) * near, (cy - hy) * near, (cy + hy) * near, near, far),
      static_cast<float>(d - 0.3), static_cast<float>(d + 4.0)};
}

ViewFraction view_fraction(const ViewSetup& setup, Vec3 p) {
  const Vec3 ndc = transform_point(setup.projection * setup.view, p);
  return {0.5 * (ndc.x + 1.0), 0.5 * (1.0 - ndc.y)};
}

}  // namespace vibro::gl
