// The small numbers of the event core, in one place, each with the reason for its value. They
// depend on the model's scales only, never on the integrator's tolerance: runs at different
// tolerances then make the same decisions (the same impacts listed, the same chatter summed), so
// their event lists can be compared event by event.
#pragma once

#include <cmath>

#include "core/integrators/ode.h"
#include "core/model/model.h"

namespace vibro {

struct EventTolerances {
  // sqrt(R/g), s: the model's natural time unit (a small swing's period over 2π).
  double time_scale = 1.0;
  // Chatter series that would last less than this are summed in closed form (MODEL.md, event 4):
  // 1e-4·time_scale. Summing errs by about chatter_time²/time_scale (the accelerations change that
  // little over the summed flights), 1e-8·time_scale, far below what a user resolves.
  double chatter_time = 0.0;
  // Speeds below this are zero, rad/s: 1e-13 of the speed scale, round-off of a speed snapped
  // to zero and carried through an impact.
  double v_eps = 0.0;
  // A free acceleration this small (times 1 + |φ|) is zero in the stick test, rad/s²: 4ε·g/R,
  // the round-off of the gravity term for an angle known to an ulp. sin(fl(−2π)) is 2.4e-16,
  // not 0: a pellet put at rest at the bottom slid off it by 1e-16 rad and turned at times set
  // by round-off alone, which every method put elsewhere.
  double accel_round_off = 0.0;
  // Touching pellets closer in speed than this move on together, rad/s: 1e-9 of the speed
  // scale. Closer speeds would give a next collision within round-off of the gap.
  double v_merge = 0.0;
  // Neighbours closer than this (relative to the angle scale) touch at an instant, rad: an
  // inelastic cascade closes gaps geometrically and ends only when the near-touching ones are
  // treated together; 1e-10 stays far above the round-off of an unwrapped angle.
  double contact_distance = 1e-10;
  // A body at rest this close to an armed limiter (relative to the angle scale) sits on it: the
  // angle of a body snapped onto a limiter, up to round-off.
  double on_limiter = 1e-14;
  // Pellets pressed together that would part by less than this (relative to the angle scale)
  // before they meet again stay together: a hundred ulps of the angles, below which the gap is
  // round-off. Elastic pellets (k_c = 1) pressed together bounced 1e-8 s apart and 1e-15 rad
  // high, a count of collisions that every tolerance put otherwise.
  double flight_round_off = 1e2 * 2.220446049250313e-16;
  // At t = 0 a pellet this close to a limiter starts on it, rad: a scene that writes the
  // limiter's angle in decimals (0.7853981633974483) means that limiter. 1e-12 of the starting
  // angles' scale (see place_radii).
  double start_on_limiter = 1e-12;
  // Roots this close in time are one instant (MODEL.md, event 5).
  double simultaneous(double t) const { return 1e-12 * (1.0 + std::abs(t)); }
  // Instants at one time before the run is stopped as an unresolved Zeno sequence: a cascade is
  // resolved within one instant, so even a long chain of pellets needs far fewer.
  int max_same_instant = 1000;
};

// The tolerances for a model, from its time scale and the pellets' initial speeds.
EventTolerances event_tolerances(const Model& model);

// The radii of "at one place" in a state, rad: the relative tolerances above times one angle
// scale for every pellet, 1 + the largest |φ|, the size of the unwrapped angles' round-off.
// Pellets at one place can carry unwrapped angles 2π apart (0.04 and 6.32): radii from each
// one's own angle put one of them on a limiter and the other not, and their body slid through
// the limiter.
struct PlaceRadii {
  double contact = 0.0;
  double on_limiter = 0.0;
  double flight_round_off = 0.0;
};
PlaceRadii place_radii(const EventTolerances& tol, const Vec& y);

}  // namespace vibro
