// One event instant (MODEL.md, "Events"): everything that happens at one time t, resolved in
// named phases, each one function:
//   1. snap      the crossings found by the root finder are put exactly onto their events (the
//                angle onto the limiter, the speed to zero, two pellets onto one place), and the
//                contacts of the instant are listed, standing ones included (snap.cpp);
//   2. impacts   limiter impacts and collisions among the contacts, until nothing approaches
//                (strike, over impacts.h);
//   3. join      touching pellets that move on together become one body (join_bodies, over
//                contacts.h), each at its momentum's speed (merged_speed);
//   4. chatter   a body pressed back onto the limiter it just left: the series is summed
//                (sum_chatter, over chatter.h);
//   5. modes     each body slides, sticks or rests (set_mode), and the event that says how its
//                motion changed (mode_change).
// Phases 2 to 5 are in instant.cpp.
#pragma once

#include <vector>

#include "core/events/contacts.h"
#include "core/events/event.h"
#include "core/events/event_tolerances.h"
#include "core/events/impacts.h"
#include "core/events/interval.h"
#include "core/events/watch.h"
#include "core/model/model.h"
#include "core/model/motion.h"

namespace vibro {

// What the crossings of an instant decided for one pellet. A release or separation fires at the
// root of a threshold (friction's capacity, the press between two parts), where a test of the
// same threshold is decided by round-off: the crossing has decided it, and the pellets it pulled
// leave their hold whatever the test says.
struct PelletAtInstant {
  bool reversed = false;  // its body's speed reached zero
  bool released = false;  // its body's release or separation watch fired
  int pulled = 0;         // the way it was pulled free (±1), or 0
};

// The contacts at an instant, and what its crossings decided per pellet.
struct InstantContacts {
  std::vector<LimiterContact> limiters;
  std::vector<PairContact> pairs;
  std::vector<PairContact> parting;      // the pairs where a body's separation watch fired
  std::vector<PelletAtInstant> pellets;  // one per pellet of the model
};

// What an instant leaves behind.
struct InstantOutcome {
  std::vector<Body> bodies;     // the next interval's bodies, with their modes
  std::vector<Event> events;    // with times and angles
  std::vector<bool> touched;    // per pellet: its motion interval ends here
  double kinetic_change = 0.0;  // J: kinetic energy gained at the instant (≤ 0: impact losses)
  // A pellet two of the instant's impacts closed on at once (shared_by_closings), whose order
  // decided the outcome; -1 if none, or if the cascade went to its plastic limit (which no
  // order changes).
  int unordered = -1;
};

// Phase 1 at the end of an interval: the crossings (sorted by time, within one instant) of the
// interval's watches, snapped in y. `armed` says which limiters act.
InstantContacts snap(const Model& model, const EventTolerances& tol, const MotionInterval& interval,
                     const std::vector<Crossing>& crossings,
                     const std::vector<Neighbours>& neighbours, const std::vector<bool>& armed,
                     Vec& y);

// Phase 1 at t = 0: pellets that start on an armed limiter strike it if they move, or rest on it.
InstantContacts initial_contacts(const Model& model, const EventTolerances& tol, Vec& y);

// The bodies before the first instant: each pellet alone, stuck if it starts at rest.
std::vector<Body> initial_bodies(const Model& model, const Vec& y);

// Phases 2 to 5. `before` are the bodies of the interval that ends at t; y (speeds) and `armed`
// are updated in place.
InstantOutcome resolve_instant(const Model& model, const EventTolerances& tol, double t,
                               const std::vector<Body>& before, const InstantContacts& contacts,
                               Vec& y, std::vector<bool>& armed);

}  // namespace vibro
