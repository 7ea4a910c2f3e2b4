// Phases 2 to 5 of an instant (instant.h); phase 1, the snap, is in snap.cpp.
#include "core/events/instant.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/events/chatter.h"
#include "core/model/dynamics.h"

namespace vibro {
namespace {

// One pellet as the instant meets it, and the limiter its impacts struck.
struct Arrival {
  double v = 0.0;   // rad/s: its speed after the snap, before any impact
  int body = -1;    // its body in the interval that ends at the instant (bodies partition pellets)
  int struck = -1;  // the limiter it struck at this instant (its last such impact), or −1
};

// What the phases read: the instant's inputs, and each pellet's arrival.
struct Instant {
  const Model& model;
  const EventTolerances& tol;
  double t;                         // s
  const std::vector<Body>& before;  // the bodies of the interval that ends at t
  const InstantContacts& contacts;  // from the snap
  std::vector<Arrival> pellets;     // one per pellet of the model
};

std::vector<Arrival> arrivals(const Model& model, const std::vector<Body>& before, const Vec& y) {
  std::vector<Arrival> pellets(model.size());
  for (int i = 0; i < model.size(); ++i) pellets[i].v = y[dphi_index(i)];
  for (std::size_t b = 0; b < before.size(); ++b)
    for (int i : before[b].members) pellets[i].body = static_cast<int>(b);
  return pellets;
}

// J: pellet i's kinetic energy at speed v (rad/s).
double kinetic(const Model& model, int i, double v) {
  return 0.5 * model.pellets[i].m * model.R * model.R * v * v;
}

// The event at time t, with the angle of its first pellet.
Event stamped(Event e, double t, const Vec& y) {
  e.t = t;
  if (!e.pellets.empty()) e.phi = y[phi_index(e.pellets[0])];
  return e;
}

// The limiter a body is pressed against, if any: a contact of this instant.
struct Support {
  int limiter = -1;
  int side = 0;
};

Support support_of(const Body& body, const InstantContacts& contacts,
                   const std::vector<bool>& armed) {
  for (const LimiterContact& c : contacts.limiters)
    for (int i : body.members)
      if (c.pellet == i && armed[c.limiter]) return {c.limiter, c.side};
  return {};
}

// Phase 2: the impacts among the contacts (impacts.h), written into the speeds of y; each listed
// at t, its pellets touched, and the kinetic energy they change counted. Returns them unstamped,
// for the chatter phase to read who struck whom.
std::vector<Event> strike(Instant& in, Vec& y, std::vector<bool>& armed, InstantOutcome& out) {
  const Model& model = in.model;
  const InstantContacts& c = in.contacts;
  out.unordered = shared_by_closings(model, y, armed, c.limiters, c.pairs, in.tol.v_eps);
  std::vector<Event> impacts =
      resolve_impacts(model, y, armed, c.limiters, c.pairs, ImpactOptions{.v_eps = in.tol.v_eps});
  // At the plastic limit no order of the impacts changes the outcome.
  if (std::any_of(impacts.begin(), impacts.end(),
                  [](const Event& e) { return e.impacts_resolved > 0; }))
    out.unordered = -1;
  for (int i = 0; i < model.size(); ++i)
    out.kinetic_change += kinetic(model, i, y[dphi_index(i)]) - kinetic(model, i, in.pellets[i].v);
  for (const Event& e : impacts) {
    for (int i : e.pellets) out.touched[i] = true;
    if (e.kind == EventKind::limiter) in.pellets[e.pellets[0]].struck = e.limiter;
    out.events.push_back(stamped(e, in.t, y));
  }
  return impacts;
}

// Phase 3: the bodies after the impacts (contacts.h, join_touching); the pairs a separation
// watch parted stay apart.
std::vector<Body> join_bodies(const Instant& in, const Vec& y, const std::vector<bool>& armed) {
  std::vector<PairContact> joinable = in.contacts.pairs;
  const std::vector<PairContact>& parting = in.contacts.parting;
  std::erase_if(joinable, [&](const PairContact& p) {
    return std::find(parting.begin(), parting.end(), p) != parting.end();
  });
  const JoinCriteria criteria{in.tol.v_merge, in.tol.chatter_time,
                              place_radii(in.tol, y).flight_round_off};
  return join_touching(in.model, in.t, y, joinable, in.contacts.limiters, armed, criteria);
}

// A merge is plastic: a body moves with its momentum's speed (rad/s), unless that drives it into
// a limiter holding one of its members, which takes that momentum (a pellet parting from one its
// limiter had just stopped, joined to it by their quick chatter, would drag it through). The
// kinetic energy the merge changes is counted; y is left to the caller.
double merged_speed(const Model& model, const Body& body, const Support& support, const Vec& y,
                    InstantOutcome& out) {
  double P = 0.0, M = 0.0;
  for (int i : body.members) {
    P += model.pellets[i].m * y[dphi_index(i)];
    M += model.pellets[i].m;
  }
  double speed = P / M;
  if (support.limiter >= 0 && speed * support.side < 0.0) speed = 0.0;
  for (int i : body.members)
    out.kinetic_change += kinetic(model, i, speed) - kinetic(model, i, y[dphi_index(i)]);
  return speed;
}

// The restitution that a body leaving the fixed limiter it struck at this instant meets at each
// of its next impacts there, or −1 if it has none: a lone pellet's is its limiter's k. A body
// that came in as one (its members at one speed) and whose impacts at this instant stayed among
// its members and the limiter leaves at one fraction of that speed, the same at every impact
// after: the cascade is linear in the speed.
double series_restitution(const Instant& in, const Body& body, int limiter, double speed,
                          const std::vector<Event>& impacts) {
  if (body.members.size() == 1) return in.model.limiters[limiter].k;
  auto member = [&](int i) {
    return std::find(body.members.begin(), body.members.end(), i) != body.members.end();
  };
  for (const Event& e : impacts)
    if (std::any_of(e.pellets.begin(), e.pellets.end(), member) &&
        !std::all_of(e.pellets.begin(), e.pellets.end(), member))
      return -1.0;
  const double v0 = in.pellets[body.leader()].v;
  for (int i : body.members)
    if (in.pellets[i].v != v0) return -1.0;
  return v0 != 0.0 ? -speed / v0 : -1.0;
}

Event chatter_event(const Body& body, int limiter, double speed, const ChatterSeries& series) {
  Event e;
  e.kind = EventKind::chatter;
  e.pellets = body.members;
  e.limiter = limiter;
  e.dphi_before.assign(body.members.size(), speed);
  e.dphi_after.assign(body.members.size(), 0.0);
  e.impacts_resolved = series.impacts;
  e.t_accumulation = series.t_star;
  return e;
}

// Phase 4: a body leaving at `speed` (rad/s) the armed limiter it struck at this instant,
// pressed back (free acceleration a_free, rad/s²) so hard that the rest of its impacts would
// last less than the chatter time: their series is summed (chatter.h) into one chatter event at
// its accumulation time, and the body is left at rest against that limiter (speed 0, support
// set, the kinetic energy it had counted as lost).
void sum_chatter(const Instant& in, const std::vector<Event>& impacts,
                 const std::vector<bool>& armed, const Body& body, double a_free, double& speed,
                 Support& support, Vec& y, InstantOutcome& out) {
  int struck = -1;
  for (int i : body.members) struck = std::max(struck, in.pellets[i].struck);
  if (!(std::abs(speed) > in.tol.v_eps) || struck < 0 || !armed[struck]) return;
  const double k = series_restitution(in, body, struck, speed, impacts);
  if (k < 0.0) return;
  const int side = speed > 0.0 ? 1 : -1;
  const double theta = in.model.limiters[struck].angle;
  const auto series = chatter_series(in.model, in.t, theta, side, std::abs(speed), k, a_free);
  if (!series || series->t_next / (1.0 - series->r) > in.tol.chatter_time) return;
  const Event e = chatter_event(body, struck, speed, *series);
  for (int i : body.members) {
    out.kinetic_change -= kinetic(in.model, i, speed);
    y[dphi_index(i)] = 0.0;
    out.touched[i] = true;
  }
  out.events.push_back(stamped(e, series->t_star, y));
  speed = 0.0;
  support = {struck, side};
}

// Phase 5 for one body moving at v (rad/s): slide, stick or rest against `support`. A body pulled
// free (±1) by a crossing slides that way whatever the stick test says at the root.
void set_mode(Body& body, double v, const Support& support, double a_free, double capacity,
              int pulled, const EventTolerances& tol) {
  if (std::abs(v) > tol.v_eps) {
    body.mode = Mode::sliding;
    body.s = v > 0.0 ? 1 : -1;
  } else if (pulled != 0) {
    body.mode = Mode::sliding;
    body.s = pulled;
  } else if (support.limiter >= 0 && !(support.side * a_free > capacity)) {
    body.mode = Mode::resting;
    body.limiter = support.limiter;
    body.side = support.side;
  } else if (support.limiter >= 0) {
    body.mode = Mode::sliding;
    body.s = support.side;
  } else if (std::abs(a_free) <= capacity) {
    body.mode = Mode::stuck;
  } else {
    body.mode = Mode::sliding;
    body.s = a_free > 0.0 ? 1 : -1;
  }
}

// The way (±1) the crossings pulled the body free, if they pulled every member that way; 0 if
// not: the crossing spoke for the pellets it pulled, as long as no other pellet joined them.
int pulled_way(const Body& body, const InstantContacts& contacts) {
  const int way = contacts.pellets[body.leader()].pulled;
  return std::all_of(body.members.begin(), body.members.end(),
                     [&](int i) { return contacts.pellets[i].pulled == way; })
             ? way
             : 0;
}

// A sliding pellet that no impact touched, whose speed at the instant is within v_eps of zero
// and that does not go on the way it went, reaches zero speed here: its own reversal lies within
// round-off of this instant, and a run would list it or not as its steps fell. Its speed may
// have turned already (its root just before the instant, put a little late): going on its new
// way, the run would list the reversal nowhere.
bool snapped_to_a_halt(const Body& held, double v, bool touched, const Body& now,
                       const EventTolerances& tol) {
  if (held.mode != Mode::sliding || touched || v == 0.0 || std::abs(v) > tol.v_eps) return false;
  return now.mode != Mode::sliding || now.s != held.s;
}

// Phase 5's event for a body now in its mode at `speed`: a member that reached zero speed (its
// body was sliding) makes a reversal, or a stick where the body now holds; a member let go from a
// hold makes a release if the body slides. None otherwise.
std::optional<Event> mode_change(const Instant& in, const Body& body, double speed,
                                 const std::vector<bool>& touched) {
  bool reversed = false, released = false;
  int left = -1;  // the limiter a released member rested against
  for (int i : body.members) {
    const Body& held = in.before[in.pellets[i].body];
    const PelletAtInstant& crossed = in.contacts.pellets[i];
    reversed = reversed || crossed.reversed ||
               snapped_to_a_halt(held, in.pellets[i].v, touched[i], body, in.tol);
    if (crossed.released && held.mode != Mode::sliding) {
      released = true;
      if (held.mode == Mode::resting) left = held.limiter;
    }
  }
  Event e;
  if (reversed) {
    e.kind = body.mode == Mode::sliding ? EventKind::reversal : EventKind::stick;
    e.limiter = body.mode == Mode::resting ? body.limiter : -1;
  } else if (released && body.mode == Mode::sliding) {
    e.kind = EventKind::release;
    e.limiter = left;
  } else {
    return std::nullopt;
  }
  e.pellets = body.members;
  e.dphi_before.assign(body.members.size(), 0.0);
  e.dphi_after.assign(body.members.size(), speed);
  return e;
}

// Phases 4 and 5 for one body of the join: its plastic merge, its chatter, its mode, its speed
// written into y, and the event that says how its motion changed.
void settle(const Instant& in, const std::vector<Event>& impacts, const std::vector<bool>& armed,
            Body& body, Vec& y, InstantOutcome& out) {
  const double phi = y[phi_index(body.leader())];
  const double a_free = body_free_acceleration(in.model, body, in.t, phi);
  Support support = support_of(body, in.contacts, armed);
  double speed = merged_speed(in.model, body, support, y, out);
  sum_chatter(in, impacts, armed, body, a_free, speed, support, y, out);
  const double capacity =
      stick_capacity(in.model, phi) + in.tol.accel_round_off * (1.0 + std::abs(phi));
  set_mode(body, speed, support, a_free, capacity, pulled_way(body, in.contacts), in.tol);
  if (std::abs(speed) <= in.tol.v_eps) speed = 0.0;
  for (int i : body.members) y[dphi_index(i)] = speed;
  const std::optional<Event> e = mode_change(in, body, speed, out.touched);
  if (!e) return;
  out.events.push_back(stamped(*e, in.t, y));
  for (int i : body.members) out.touched[i] = true;
}

}  // namespace

std::vector<Body> initial_bodies(const Model& model, const Vec& y) {
  std::vector<Body> bodies;
  for (int i = 0; i < model.size(); ++i) {
    Body b;
    b.members = {i};
    const double v = y[dphi_index(i)];
    b.mode = v == 0.0 ? Mode::stuck : Mode::sliding;
    b.s = v < 0.0 ? -1 : 1;
    bodies.push_back(b);
  }
  return bodies;
}

InstantOutcome resolve_instant(const Model& model, const EventTolerances& tol, double t,
                               const std::vector<Body>& before, const InstantContacts& contacts,
                               Vec& y, std::vector<bool>& armed) {
  Instant in{model, tol, t, before, contacts, arrivals(model, before, y)};
  InstantOutcome out;
  out.touched.assign(model.size(), false);
  const std::vector<Event> impacts = strike(in, y, armed, out);
  out.bodies = join_bodies(in, y, armed);
  for (Body& body : out.bodies) settle(in, impacts, armed, body, y, out);
  return out;
}

}  // namespace vibro
