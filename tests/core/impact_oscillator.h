// The impact oscillator of the sweep, orbit and Lyapunov tests: a forced pendulum (m = 0.1 kg on
// R = 0.5 m, F0 = 0.3 N, frictionless) striking a stop at the bottom (k = 0.8), from φ = 0.1 rad
// at rest. Period doubling near Ω = 5.56 rad/s, a fold at 7.81, chaos near 3.25.
#pragma once

#include "core/model/model.h"

namespace vibro::testing {

inline Model impact_oscillator(double Omega = 5.0) {
  Model m;
  m.R = 0.5;
  m.pellets = {{0.1, 0.1, 0.0, {0.3, Omega, 0.0}}};
  m.limiters = {{0.0, 0.8, false, -1, {}}};
  return m;
}

}  // namespace vibro::testing
