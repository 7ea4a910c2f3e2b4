// How the pellets move during one segment (between two event instants).
// Pellets in contact that move together form one Body; a lone pellet is a body of one.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

namespace vibro {

enum class Mode {
  sliding,  // moving with sign(dphi) = s; kinetic friction
  stuck,    // held by static friction
  resting,  // at rest against an armed limiter
};

struct Body {
  std::vector<int> members;  // in +phi order around the circle; members[0] carries the state
  Mode mode = Mode::sliding;
  int s = 1;         // sliding direction, ±1
  int limiter = -1;  // resting: the limiter it rests against
  int side = 0;      // resting: +1 if the body lies on the phi > angle side of the limiter
  int leader() const { return members.front(); }
};

// State layout: three components per pellet: phi, dphi, and the work done on the pellet by the
// force and friction (J), whose sum closes the energy balance that estimates the error.
inline int phi_index(int pellet) { return 3 * pellet; }
inline int dphi_index(int pellet) { return 3 * pellet + 1; }
inline int work_index(int pellet) { return 3 * pellet + 2; }

// An angle's distance from the nearest whole turn, that is from the bottom of the circle: the size
// the tolerances hold it relative to (OdeSystem::period), whatever turns brought it there.
inline double angle_size(double phi) {
  return std::abs(std::remainder(phi, 2.0 * std::numbers::pi));
}

}  // namespace vibro
