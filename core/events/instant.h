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
#include "core/events/event_list.h"
#include "core/events/event_tolerances.h"
#include "core/events/impacts.h"
#include "core/events/interval.h"
#include "core/events/watch.h"
#include "core/model/dynamics.h"
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
  EventList events;             // with times and angles
  std::vector<bool> touched;    // per pellet: its motion interval ends here
  double kinetic_change = 0.0;  // J: kinetic energy gained at the instant (≤ 0: impact losses)
  // A pellet two of the instant's impacts closed on at once (shared_by_closings), whose order
  // decided the outcome; -1 if none, or if the cascade went to its plastic limit (which no
  // order changes).
  int unordered = -1;
};

// One pellet as the instant meets it, and the limiter its impacts struck.
struct Arrival {
  double v = 0.0;   // rad/s: its speed after the snap, before any impact
  int body = -1;    // its body in the interval that ends at the instant (bodies partition pellets)
  int struck = -1;  // the limiter it struck at this instant (its last such impact), or −1
};

// What a run's instants reuse from one to the next: the contacts the snap lists, the outcome
// the phases leave, and their scratch. Everything in it is sized by the model (its pellets and
// limiters are fixed) and by the instant's contacts, so a run's instants stop allocating once it
// has met its largest. One per run (a run is one thread's).
struct InstantWorkspace {
  InstantContacts contacts;  // phase 1's result
  InstantOutcome outcome;    // phases 2 to 5's
  // Phase 1's scratch.
  std::vector<bool> at_limiter;  // per pellet
  std::vector<Crossing> ordered;
  std::vector<LimiterContact> limiters;
  std::vector<PairContact> apart;
  Vec before_touching;  // the state before touching pellets are snapped onto one place
  // Phases 2 to 5's.
  std::vector<Arrival> arrivals;  // per pellet
  std::vector<PairContact> joinable;
  ImpactScratch impacts;
  JoinScratch join;
};

// Phase 1 at the end of an interval: the crossings (sorted by time, within one instant) of the
// interval's watches, snapped in y, into ws.contacts. `armed` says which limiters act.
void snap(const Model& model, const EventTolerances& tol, const MotionInterval& interval,
          const std::vector<Crossing>& crossings, const std::vector<Neighbours>& neighbours,
          const std::vector<bool>& armed, Vec& y, InstantWorkspace& ws);
// The same, returned.
InstantContacts snap(const Model& model, const EventTolerances& tol, const MotionInterval& interval,
                     const std::vector<Crossing>& crossings,
                     const std::vector<Neighbours>& neighbours, const std::vector<bool>& armed,
                     Vec& y);

// Phase 1 at t = 0: pellets that start on an armed limiter strike it if they move, or rest on it.
InstantContacts initial_contacts(const Model& model, const EventTolerances& tol, Vec& y);

// The bodies before the first instant: each pellet alone, stuck if it starts at rest.
std::vector<Body> initial_bodies(const Model& model, const Vec& y);

// Phases 2 to 5, into ws.outcome. `before` are the bodies of the interval that ends at t (not
// ws.outcome.bodies, which the join overwrites); y (speeds) and `armed` are updated in place.
// `contacts` may be ws.contacts; `law` is the model's.
void resolve_instant(const Model& model, const EventTolerances& tol, const SlidingLaw& law,
                     double t, const std::vector<Body>& before, const InstantContacts& contacts,
                     Vec& y, std::vector<bool>& armed, InstantWorkspace& ws);
// The same, returned.
InstantOutcome resolve_instant(const Model& model, const EventTolerances& tol, double t,
                               const std::vector<Body>& before, const InstantContacts& contacts,
                               Vec& y, std::vector<bool>& armed);

}  // namespace vibro
