// Where the phase cylinder sits in scene space: radius 1 about the z axis, φ̇ mapped onto
// z ∈ [-kHalfHeight, kHalfHeight]. A square-ish box reads well from any side.
#pragma once

#include "render/gl/cylinder_scene.h"
#include "render/gl/view_math.h"

namespace vibro::gl {

inline constexpr double kHalfHeight = 0.9;

// Maps φ̇ linearly onto the cylinder's height.
struct HeightScale {
  double lo = -1.0;  // φ̇ at the bottom rim
  double hi = 1.0;   // φ̇ at the top rim

  double z(double dphi) const { return kHalfHeight * (2.0 * (dphi - lo) / (hi - lo) - 1.0); }
};

// The scene's own φ̇ range, or the branches' range with a margin so the trajectory clears
// the rims; a flat or empty trajectory gets a unit-wide range about its value (or 0).
HeightScale height_scale(const CylinderScene& scene);

inline Vec3 on_cylinder(double phi, double z) { return {std::cos(phi), std::sin(phi), z}; }

}  // namespace vibro::gl
