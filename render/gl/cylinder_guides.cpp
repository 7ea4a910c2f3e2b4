#include "render/gl/cylinder_guides.h"

#include <numbers>

namespace vibro::gl {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr int kRingSegments = 180;

void add_segment(LineSet& lines, Vec3 a, Vec3 b, std::uint8_t grey) {
  const Rgb8 colour{grey, grey, grey};
  lines.vertices.push_back(make_vertex(a, {}, colour));
  lines.vertices.push_back(make_vertex(b, {}, colour));
}

// A ring at height z; with `dashed`, every other segment group is left out.
void add_ring(LineSet& lines, double z, std::uint8_t grey, bool dashed) {
  constexpr int kDash = 3;  // segments per dash
  for (int i = 0; i < kRingSegments; ++i) {
    if (dashed && (i / kDash) % 2 == 1) continue;
    add_segment(lines, on_cylinder(kTwoPi * i / kRingSegments, z),
                on_cylinder(kTwoPi * (i + 1) / kRingSegments, z), grey);
  }
}

}  // namespace

Mesh cylinder_wall() {
  constexpr int kSegments = 96;
  // Cool light grey: a tint, not a colour that could be mistaken for a branch.
  constexpr Rgb8 kTint{150, 160, 175};
  constexpr std::uint8_t kAlpha = 38;
  Mesh mesh;
  for (int i = 0; i < kSegments; ++i) {
    const double phi = kTwoPi * i / kSegments;
    for (double z : {-kHalfHeight, kHalfHeight}) {
      mesh.vertices.push_back(
          make_vertex(on_cylinder(phi, z), on_cylinder(phi, 0.0), kTint, kAlpha));
    }
    const auto bottom = static_cast<std::uint32_t>(2 * i);
    const auto next = static_cast<std::uint32_t>(2 * ((i + 1) % kSegments));
    mesh.indices.insert(mesh.indices.end(), {bottom, next, bottom + 1, next, next + 1, bottom + 1});
  }
  return mesh;
}

LineSet limiter_lines(const std::vector<double>& angles) {
  LineSet lines;
  lines.width_px = 2.0f;
  for (double theta : angles) {
    if (!std::isfinite(theta)) continue;
    add_segment(lines, on_cylinder(theta, -kHalfHeight), on_cylinder(theta, kHalfHeight), 20);
  }
  return lines;
}

std::vector<LineSet> guide_lines(const HeightScale& scale) {
  LineSet rims;
  rims.width_px = 1.3f;
  add_ring(rims, -kHalfHeight, 90, false);
  add_ring(rims, kHalfHeight, 90, false);

  LineSet fine;
  fine.width_px = 1.0f;
  if (scale.lo < 0.0 && scale.hi > 0.0) add_ring(fine, scale.z(0.0), 130, true);
  add_segment(fine, {0.0, 0.0, -kHalfHeight}, {0.0, 0.0, kHalfHeight}, 170);

  LineSet ticks;
  ticks.width_px = 1.3f;
  for (int deg = 0; deg < 360; deg += 30) {
    const double phi = deg * std::numbers::pi / 180.0;
    const double length = deg == 0 ? 0.16 : deg % 90 == 0 ? 0.10 : 0.05;
    add_segment(ticks, on_cylinder(phi, -kHalfHeight),
                {(1.0 + length) * std::cos(phi), (1.0 + length) * std::sin(phi), -kHalfHeight},
                deg == 0 ? 40 : 90);
  }
  return {rims, fine, ticks};
}

}  // namespace vibro::gl
