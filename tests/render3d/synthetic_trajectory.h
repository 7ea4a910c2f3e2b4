// A made-up trajectory for the 3-D panel tests: a damped spiral on the phase cylinder cut
// into branches, like a pellet losing energy between impacts.
#pragma once

#include <cmath>

#include "render/gl/cylinder_scene.h"

namespace vibro::gl::testing {

inline CylinderScene damped_spiral_scene(int branches = 5, int points_per_branch = 400) {
  CylinderScene scene;
  double t = 0.0;
  const double dt = 0.01;
  for (int b = 0; b < branches; ++b) {
    CylinderBranch branch;
    branch.index = b;
    for (int i = 0; i < points_per_branch; ++i, t += dt) {
      const double decay = std::exp(-0.12 * t);
      // φ winds round while φ̇ oscillates and decays: a spiral on the cylinder.
      branch.points.push_back(
          {2.0 * t + 1.5 * decay * std::sin(3.0 * t), 2.0 + 4.0 * decay * std::cos(3.0 * t)});
    }
    scene.branches.push_back(std::move(branch));
  }
  scene.limiter_angles = {0.9, 2.6, 4.4};
  return scene;
}

}  // namespace vibro::gl::testing
