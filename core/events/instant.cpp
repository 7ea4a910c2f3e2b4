// Phases 2 to 5 of an instant (instant.h); phase 1, the snap, is in snap.cpp.
#include "core/events/instant.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <utility>

#include "core/events/chatter.h"
#include "core/model/dynamics.h"

namespace vibro {
namespace {

// What the phases read: the instant's inputs, and each pellet's arrival.
struct Instant {
  const Model& model;
  const EventTolerances& tol;
  double t;                         // s
  const std::vector<Body>& before;  // the bodies of the interval that ends at t
  const InstantContacts& contacts;  // from the snap
  std::vector<Arrival>& pellets;    // one per pellet of the model
};

void arrive(const Model& model, const std::vector<Body>& before, const Vec& y,
            std::vector<Arrival>& pellets) {
  pellets.assign(model.size(), Arrival{});
  for (int i = 0; i < model.size(); ++i) pellets[i].v = y[dphi_index(i)];
  for (std::size_t b = 0; b < before.size(); ++b)
    for (int i : before[b].members) pellets[i].body = static_cast<int>(b);
}

// J: pellet i's kinetic energy at speed v (rad/s).
double kinetic(const Model& model, int i, double v) {
  return 0.5 * model.pellets[i].m * model.R * model.R * v * v;
}

// The event put at time t, with the angle of its first pellet.
void stamp(Event& e, double t, const Vec& y) {
  e.t = t;
  if (!e.pellets.empty()) e.phi = y[phi_index(e.pellets[0])];
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

// Phase 2: the impacts among the contacts (impacts.h), written into the speeds of y and listed
// first in out.events; each at t, its pellets touched, and the kinetic energy they change
// counted. Returns how many, for the chatter phase to read who struck whom.
std::size_t strike(Instant& in, Vec& y, std::vector<bool>& armed, InstantOutcome& out,
                   ImpactScratch& scratch) {
  const Model& model = in.model;
  const InstantContacts& c = in.contacts;
  out.unordered = shared_by_closings(model, y, armed, c.limiters, c.pairs, in.tol.v_eps, scratch);
  resolve_impacts(model, y, armed, c.limiters, c.pairs, ImpactOptions{.v_eps = in.tol.v_eps},
                  scratch, out.events);
  // At the plastic limit no order of the impacts changes the outcome.
  if (std::any_of(out.events.begin(), out.events.end(),
                  [](const Event& e) { return e.impacts_resolved > 0; }))
    out.unordered = -1;
  for (int i = 0; i < model.size(); ++i)
    out.kinetic_change += kinetic(model, i, y[dphi_index(i)]) - kinetic(model, i, in.pellets[i].v);
  for (Event& e : out.events) {
    for (int i : e.pellets) out.touched[i] = true;
    if (e.kind == EventKind::limiter) in.pellets[e.pellets[0]].struck = e.limiter;
    stamp(e, in.t, y);
  }
  return out.events.size();
}

// Phase 3: the bodies after the impacts (contacts.h, join_touching), into ws.outcome.bodies;
// the pairs a separation watch parted stay apart.
void join_bodies(const Instant& in, const SlidingLaw& law, const Vec& y,
                 const std::vector<bool>& armed, InstantWorkspace& ws) {
  std::vector<PairContact>& joinable = ws.joinable;
  joinable.assign(in.contacts.pairs.begin(), in.contacts.pairs.end());
  const std::vector<PairContact>& parting = in.contacts.parting;
  std::erase_if(joinable, [&](const PairContact& p) {
    return std::find(parting.begin(), parting.end(), p) != parting.end();
  });
  const JoinCriteria criteria{in.tol.v_merge, in.tol.chatter_time,
                              place_radii(in.tol, y).flight_round_off};
  join_touching(in.model, law, in.t, y, joinable, in.contacts.limiters, armed, criteria, ws.join,
                ws.outcome.bodies);
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
                          std::span<const Event> impacts) {
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

// The chatter event of a body leaving `limiter` at `speed`, summed as `series` says.
void fill_chatter(Event& e, const Body& body, int limiter, double speed,
                  const ChatterSeries& series) {
  e.kind = EventKind::chatter;
  e.pellets = body.members;
  e.limiter = limiter;
  e.dphi_before.assign(body.members.size(), speed);
  e.dphi_after.assign(body.members.size(), 0.0);
  e.impacts_resolved = series.impacts;
  e.t_accumulation = series.t_star;
}

// Phase 4: a body leaving at `speed` (rad/s) the armed limiter it struck at this instant,
// pressed back (free acceleration a_free, rad/s²) so hard that the rest of its impacts would
// last less than the chatter time: their series is summed (chatter.h) into one chatter event at
// its accumulation time, and the body is left at rest against that limiter (speed 0, support
// set, the kinetic energy it had counted as lost).
void sum_chatter(const Instant& in, std::size_t impacts, const std::vector<bool>& armed,
                 const Body& body, double a_free, double& speed, Support& support, Vec& y,
                 InstantOutcome& out) {
  int struck = -1;
  for (int i : body.members) struck = std::max(struck, in.pellets[i].struck);
  if (!(std::abs(speed) > in.tol.v_eps) || struck < 0 || !armed[struck]) return;
  const double k = series_restitution(in, body, struck, speed, out.events.view().first(impacts));
  if (k < 0.0) return;
  const int side = speed > 0.0 ? 1 : -1;
  const double theta = in.model.limiters[struck].angle;
  const auto series = chatter_series(in.model, in.t, theta, side, std::abs(speed), k, a_free);
  if (!series || series->t_next / (1.0 - series->r) > in.tol.chatter_time) return;
  for (int i : body.members) {
    out.kinetic_change -= kinetic(in.model, i, speed);
    y[dphi_index(i)] = 0.0;
    out.touched[i] = true;
  }
  Event& e = out.events.add();
  fill_chatter(e, body, struck, speed, *series);
  stamp(e, series->t_star, y);
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

// How a body's motion changed at the instant: the kind of its event and the limiter it names.
struct ModeChange {
  EventKind kind;
  int limiter;
};

// Phase 5's event for a body now in its mode: a member that reached zero speed (its body was
// sliding) makes a reversal, or a stick where the body now holds; a member let go from a hold
// makes a release if the body slides. None otherwise.
std::optional<ModeChange> mode_change(const Instant& in, const Body& body,
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
  if (reversed)
    return ModeChange{body.mode == Mode::sliding ? EventKind::reversal : EventKind::stick,
                      body.mode == Mode::resting ? body.limiter : -1};
  if (released && body.mode == Mode::sliding) return ModeChange{EventKind::release, left};
  return std::nullopt;
}

// Phases 4 and 5 for one body of the join: its plastic merge, its chatter, its mode, its speed
// written into y, and the event that says how its motion changed. The first `impacts` events
// of `out` are the instant's impacts.
void settle(const Instant& in, std::size_t impacts, const std::vector<bool>& armed, Body& body,
            Vec& y, InstantOutcome& out) {
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
  const std::optional<ModeChange> change = mode_change(in, body, out.touched);
  if (!change) return;
  Event& e = out.events.add();
  e.kind = change->kind;
  e.limiter = change->limiter;
  e.pellets = body.members;
  e.dphi_before.assign(body.members.size(), 0.0);
  e.dphi_after.assign(body.members.size(), speed);
  stamp(e, in.t, y);
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

void resolve_instant(const Model& model, const EventTolerances& tol, const SlidingLaw& law,
                     double t, const std::vector<Body>& before, const InstantContacts& contacts,
                     Vec& y, std::vector<bool>& armed, InstantWorkspace& ws) {
  arrive(model, before, y, ws.arrivals);
  Instant in{model, tol, t, before, contacts, ws.arrivals};
  InstantOutcome& out = ws.outcome;
  out.events.clear();
  out.touched.assign(model.size(), false);
  out.kinetic_change = 0.0;
  out.unordered = -1;
  const std::size_t impacts = strike(in, y, armed, out, ws.impacts);
  join_bodies(in, law, y, armed, ws);
  for (Body& body : out.bodies) settle(in, impacts, armed, body, y, out);
}

InstantOutcome resolve_instant(const Model& model, const EventTolerances& tol, double t,
                               const std::vector<Body>& before, const InstantContacts& contacts,
                               Vec& y, std::vector<bool>& armed) {
  InstantWorkspace ws;
  resolve_instant(model, tol, SlidingLaw(model), t, before, contacts, y, armed, ws);
  return std::move(ws.outcome);
}

}  // namespace vibro
