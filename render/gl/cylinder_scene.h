// What the 3-D phase-cylinder panel draws: one pellet's trajectory as branches on the
// cylinder (cos φ, sin φ, φ̇), the limiter angles, and where the camera stands.
#pragma once

#include <optional>
#include <vector>

#include "render/plot_spec.h"

namespace vibro::gl {

// A piece of trajectory between two events.
struct CylinderBranch {
  int index = 0;                   // the branch's number in the run: picks its colour
  std::vector<PhasePoint> points;  // (φ, φ̇) in time order; φ in rad, unwrapped or not
};

struct DphiRange {
  double lo = 0.0;
  double hi = 0.0;
};

struct CylinderScene {
  std::vector<CylinderBranch> branches;
  std::vector<double> limiter_angles;  // rad: a line along the cylinder at each
  Camera camera;
  // φ̇ values mapped onto the cylinder's height; empty: the branches' own range. Set it to
  // draw several panels on one scale.
  std::optional<DphiRange> dphi_range;
};

}  // namespace vibro::gl
