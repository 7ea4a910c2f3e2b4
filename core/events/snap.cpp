// Phase 1 of an instant (instant.h): the crossings put onto their events, and the contacts of
// the instant listed. Each step below is one function, called in order by snap():
//   snap_crossing        each crossing onto its event (limiter arrivals first)
//   add_standing         contacts that hold without a crossing: resting bodies, sliding ones on
//                        a limiter's angle
//   frontmost            a limiter meets the pellet nearest it
//   snap_touching        near-touching neighbours onto one place (contacts.h)
//   add_snapped_on_angle pellets snapped onto a limiter's angle touch it
//   add_body_pairs       members of one body touch
//   met_limiters         a pellet meets a limiter only if none lies between them
#include <algorithm>
#include <cmath>
#include <utility>

#include "core/events/instant.h"
#include "core/model/dynamics.h"

namespace vibro {
namespace {

int limiter_count(const Model& model) { return static_cast<int>(model.limiters.size()); }

// Whether pellet i at phi lies on the angle of limiter l, armed and acting on it.
bool held_on_angle(const Model& model, const PlaceRadii& radii, const std::vector<bool>& armed,
                   int i, int l, double phi) {
  return armed[l] && model.limiters[l].acts_on(i) &&
         on_limiter_angle(model.limiters[l].angle, phi, radii.on_limiter);
}

// The pellets that stay put on a limiter's angle when others meet them at an instant: bodies
// resting against one (moved halfway to meet a pellet the limiter does not stop, a resting pellet
// came off its limiter's angle and struck the limiter from behind), and pellets on the angle of a
// limiter that holds them (one sliding away after a stop went past its limiter by round-off);
// with each of them its body, whose members lie at one place (a member the limiter does not stop
// was moved halfway, taking the body off the angle).
void on_limiters(const Model& model, const PlaceRadii& radii, const std::vector<Body>& bodies,
                 const std::vector<bool>& armed, const Vec& y, std::vector<bool>& on) {
  const int n = model.size();
  on.assign(n, false);
  for (const Body& body : bodies)
    if (body.mode == Mode::resting)
      for (int i : body.members) on[i] = true;
  for (int i = 0; i < n; ++i)
    for (int l = 0; l < limiter_count(model); ++l)
      on[i] = on[i] || held_on_angle(model, radii, armed, i, l, y[phi_index(i)]);
  for (const Body& body : bodies)
    if (std::any_of(body.members.begin(), body.members.end(), [&](int i) { return on[i]; }))
      for (int i : body.members) on[i] = true;
}

// The side of a limiter a pellet starting on its angle is on: away from where it moves, or
// where its free acceleration pulls it from rest.
int start_side(const Model& model, int i) {
  const double v = model.pellets[i].dphi0;
  const double a = free_acceleration(model, i, 0.0, model.pellets[i].phi0);
  return v != 0.0 ? (v > 0.0 ? -1 : 1) : (a > 0.0 ? -1 : 1);
}

// The side of limiter l (+1 above its angle, −1 below) that pellet i, now at phi on one of the
// limiter's angles θ + 2πk, lives on, or 0 if that is not fixed: a fixed limiter that acts on a
// pellet is never passed, so the unwrapped angle stays in the turn between the limiter's angles
// that it started in.
int home_side(const Model& model, const EventTolerances& tol, int i, int l, double phi) {
  const Limiter& lim = model.limiters[l];
  if (lim.mobile || !lim.acts_on(i)) return 0;
  const double phi0 = model.pellets[i].phi0;
  const double turns0 = (phi0 - lim.angle) / kTwoPi;
  double below = std::floor(turns0);  // the index k of the angle below the start
  if (std::abs(wrap_angle(phi0 - lim.angle)) <= tol.start_on_limiter) {
    const double on = std::round(turns0);
    below = start_side(model, i) > 0 ? on : on - 1.0;
  }
  const double k = std::round((phi - lim.angle) / kTwoPi);
  return k == below ? 1 : k == below + 1.0 ? -1 : 0;
}

// The member of a body on a limiter's `side` nearest the limiter among those it acts on (the
// others pass through it: a body chattering on a limiter through its far member slid through
// the limiter when it turned on the angle, its near member taken as the one touching); −1 if
// it acts on none.
int held_member(const Model& model, const Body& body, int limiter, int side) {
  const int n = static_cast<int>(body.members.size());
  for (int k = 0; k < n; ++k) {
    const int i = body.members[side > 0 ? k : n - 1 - k];
    if (model.limiters[limiter].acts_on(i)) return i;
  }
  return -1;
}

// Another pellet the limiter acts on that touches `pellet` on the limiter's `side`, and not
// from the limiter's other side (its contact or its angle says so): it lies between them. −1 if
// none.
int pellet_between(const Model& model, const PlaceRadii& radii,
                   const std::vector<Neighbours>& neighbours,
                   const std::vector<LimiterContact>& contacts, int pellet, int limiter, int side,
                   const Vec& y) {
  for (const Neighbours& nb : neighbours) {
    const int other = side < 0 ? nb.ahead : nb.behind;
    if ((side < 0 ? nb.behind : nb.ahead) != pellet || !model.limiters[limiter].acts_on(other))
      continue;
    const bool across = std::any_of(contacts.begin(), contacts.end(), [&](const LimiterContact& c) {
      return c.pellet == other && c.limiter == limiter && c.side == -side;
    });
    if (across) continue;
    // On the limiter's other side, however close, it is not between (a pellet reversing just
    // short of a limiter does not shield the one resting on the limiter's far side).
    const double phi = y[phi_index(other)];
    if (side * wrap_angle(phi - model.limiters[limiter].angle) < -radii.on_limiter) continue;
    const double gap = y[phi_index(nb.ahead)] - y[phi_index(nb.behind)] + nb.offset;
    if (gap <= radii.contact) return other;
  }
  return -1;
}

// A sliding body within round-off of a limiter's angle touches that limiter without having
// crossed it: on the side a member that the limiter never lets pass lives on (a body snapped
// onto the angle while sliding into the limiter was taken as leaving it, on the far side, and
// slid through; round-off puts a pellet on either side); otherwise stopping as it arrives (its
// limiter watch aimed there: it lies on the side it came from, −s) or leaving it (a rebound too
// small to leave it yet: on the side it moves into, s); unless another pellet lies between. A
// cascade at this instant must find it there.
void touch_on_angle(const Model& model, const EventTolerances& tol, const PlaceRadii& radii,
                    const MotionInterval& interval, int b,
                    const std::vector<Neighbours>& neighbours, const Vec& y,
                    std::vector<LimiterContact>& contacts) {
  const Body& body = interval.bodies()[b];
  const double phi = y[phi_index(body.leader())];
  const double near = radii.on_limiter;
  // Arriving at the angle it watched, it arrives at every limiter there (two at one angle).
  bool arriving = false;
  for (const Watch& w : interval.watches())
    arriving = arriving || (w.kind == WatchKind::limiter && w.body == b && w.side == body.s &&
                            std::abs(w.target - phi) <= near);
  for (int l = 0; l < limiter_count(model); ++l) {
    if (!on_limiter_angle(model.limiters[l].angle, phi, near)) continue;
    int side = arriving ? -body.s : body.s;
    for (int i : body.members) {
      if (const int home = home_side(model, tol, i, l, phi); home != 0) {
        side = home;
        break;
      }
    }
    const int held = held_member(model, body, l, side);
    if (held >= 0 && pellet_between(model, radii, neighbours, contacts, held, l, side, y) < 0)
      contacts.push_back({held, l, side});
  }
}

// A body arriving at a limiter: all its members shift by the leader's distance to the limiter's
// angle (they move as one), the leader lands on the angle exactly, and the member nearest the
// limiter touches it from the side the body came from (the watch's −side).
void snap_onto_limiter(const Model& model, const Watch& w, const Body& body, Vec& y,
                       std::vector<bool>& at_limiter, InstantContacts& c) {
  const double shift = w.target - y[phi_index(w.pellet)];
  for (int i : body.members) {
    y[phi_index(i)] += shift;
    at_limiter[i] = true;
  }
  y[phi_index(w.pellet)] = w.target;
  const int held = held_member(model, body, w.limiter, -w.side);
  if (held >= 0) c.limiters.push_back({held, w.limiter, -w.side});
}

// Two neighbours meeting: onto one place, `target` (their winding offset) apart in unwrapped
// angle. A pellet at a limiter stays put and the other comes to it; else both meet halfway.
void snap_gap(const Watch& w, const std::vector<bool>& at_limiter, Vec& y, InstantContacts& c) {
  double& behind = y[phi_index(w.pellet)];
  double& ahead = y[phi_index(w.other)];
  if (at_limiter[w.pellet]) {
    ahead = behind - w.target;
  } else if (at_limiter[w.other]) {
    behind = ahead + w.target;
  } else {
    const double mid = 0.5 * (behind + ahead + w.target);
    behind = mid;
    ahead = mid - w.target;
  }
  c.pairs.push_back({w.pellet, w.other});
}

// A held body's separation watch fired: its members are released, the pair at the cut parts, and
// the part the forces pull off (ahead of the cut, +1, or behind it, −1) is pulled that way.
void part_at_separation(const Model& model, const Watch& w, const std::vector<Body>& bodies,
                        double t, const Vec& y, InstantContacts& c) {
  const std::vector<int>& members = bodies[w.body].members;
  for (int i : members) c.pellets[i].released = true;
  c.parting.push_back({members[w.split - 1], members[w.split]});
  const int part = pulled_off(w, model, bodies, t, y);
  const int n_members = static_cast<int>(members.size());
  for (int k = 0; k < n_members; ++k)
    if ((part > 0 && k >= w.split) || (part < 0 && k < w.split))
      c.pellets[members[k]].pulled = part;
}

// One crossing put onto its event: the state y snapped (angles onto a limiter or one place,
// speeds to zero), the contact it makes listed, and what it decided per pellet marked.
void snap_crossing(const Model& model, const MotionInterval& interval, const Crossing& crossing,
                   Vec& y, std::vector<bool>& at_limiter, InstantContacts& c) {
  const std::vector<Body>& bodies = interval.bodies();
  const Watch& w = interval.watches()[crossing.watch];
  switch (w.kind) {
    case WatchKind::limiter:
      snap_onto_limiter(model, w, bodies[w.body], y, at_limiter, c);
      break;
    case WatchKind::reversal:
      for (int i : bodies[w.body].members) {
        y[dphi_index(i)] = 0.0;
        c.pellets[i].reversed = true;
      }
      break;
    case WatchKind::gap:
      snap_gap(w, at_limiter, y, c);
      break;
    case WatchKind::normal:
      break;  // a kink of the equations, not an event: the next interval starts here
    case WatchKind::release: {
      const int way = release_direction(w, model, bodies, crossing.t, y);
      for (int i : bodies[w.body].members) {
        c.pellets[i].released = true;
        c.pellets[i].pulled = way;
      }
      break;
    }
    case WatchKind::separation:
      part_at_separation(model, w, bodies, crossing.t, y, c);
      break;
  }
}

// Contacts that hold without a crossing: bodies resting on limiters, and sliding ones on a
// limiter's angle.
void add_standing(const Model& model, const EventTolerances& tol, const PlaceRadii& radii,
                  const MotionInterval& interval, const std::vector<Neighbours>& neighbours,
                  const Vec& y, std::vector<LimiterContact>& limiters) {
  const std::vector<Body>& bodies = interval.bodies();
  for (const Body& body : bodies) {
    if (body.mode != Mode::resting) continue;
    const int held = held_member(model, body, body.limiter, body.side);
    if (held >= 0) limiters.push_back({held, body.limiter, body.side});
  }
  for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
    if (bodies[b].mode == Mode::sliding)
      touch_on_angle(model, tol, radii, interval, b, neighbours, y, limiters);
  }
}

// Each contact moved to the pellet nearest its limiter, without repeats: two bodies arriving
// together at a limiter, the limiter meets the frontmost pellet, not the one behind (taken as
// touching it, that one put the limiter between itself and the body ahead).
void frontmost(const Model& model, const PlaceRadii& radii,
               const std::vector<Neighbours>& neighbours,
               const std::vector<LimiterContact>& limiters, const Vec& y,
               std::vector<LimiterContact>& fronts) {
  fronts.clear();
  for (LimiterContact lc : limiters) {
    for (int guard = 0; guard < model.size(); ++guard) {
      const int q =
          pellet_between(model, radii, neighbours, limiters, lc.pellet, lc.limiter, lc.side, y);
      if (q < 0) break;
      lc.pellet = q;
    }
    if (std::find(fronts.begin(), fronts.end(), lc) == fronts.end()) fronts.push_back(lc);
  }
}

// The neighbours an armed limiter between them keeps apart.
void kept_apart(const Model& model, const std::vector<Neighbours>& neighbours,
                const std::vector<LimiterContact>& limiters, const std::vector<bool>& armed,
                std::vector<PairContact>& apart) {
  apart.clear();
  for (const Neighbours& nb : neighbours) {
    const PairContact pair{nb.behind, nb.ahead};
    if (separated_by_limiter(model, limiters, armed, pair)) apart.push_back(pair);
  }
}

// A pellet snapped onto a limiter's angle (onto a pellet there that the limiter does not stop)
// touches the limiter from the side it came from: without the contact, a cascade at this instant
// drove it through the limiter.
void add_snapped_on_angle(const Model& model, const PlaceRadii& radii,
                          const std::vector<bool>& armed, const Vec& unsnapped, const Vec& y,
                          std::vector<LimiterContact>& limiters) {
  for (int i = 0; i < model.size(); ++i) {
    for (int l = 0; l < limiter_count(model); ++l) {
      if (!held_on_angle(model, radii, armed, i, l, y[phi_index(i)]) ||
          held_on_angle(model, radii, armed, i, l, unsnapped[phi_index(i)]))
        continue;
      const int side = wrap_angle(unsnapped[phi_index(i)] - model.limiters[l].angle) > 0.0 ? 1 : -1;
      limiters.push_back({i, l, side});
    }
  }
}

// The members of a body touch their neighbours in it.
void add_body_pairs(const std::vector<Body>& bodies, std::vector<PairContact>& pairs) {
  for (const Body& body : bodies) {
    for (int k = 0; k + 1 < static_cast<int>(body.members.size()); ++k) {
      const PairContact pair{body.members[k], body.members[k + 1]};
      if (std::find(pairs.begin(), pairs.end(), pair) == pairs.end()) pairs.push_back(pair);
    }
  }
}

// The pellet that contact c's limiter actually meets: walking the chain of touching neighbours
// on the limiter's side, the last one the limiter acts on (they all lie at its angle, between c's
// pellet and the limiter); pellets it does not act on are walked past, one touching the limiter
// from its other side ends the walk. −1 when one in between touches the limiter from c's side
// already: c adds nothing.
int meets_limiter(const LimiterContact& c, const InstantContacts& contacts, const Model& model) {
  int q = c.pellet, nearest = c.pellet;
  for (int guard = 0; guard < model.size(); ++guard) {
    int next = -1;
    for (const PairContact& p : contacts.pairs) {
      if (c.side > 0 && p.ahead == q) next = p.behind;
      if (c.side < 0 && p.behind == q) next = p.ahead;
    }
    if (next < 0 || next == c.pellet) break;
    if (model.limiters[c.limiter].acts_on(next)) {
      const auto d = std::find_if(
          contacts.limiters.begin(), contacts.limiters.end(),
          [&](const LimiterContact& l) { return l.pellet == next && l.limiter == c.limiter; });
      if (d != contacts.limiters.end()) return d->side == c.side ? -1 : nearest;
      nearest = next;
    }
    q = next;
  }
  return nearest;
}

// The limiter contacts that remain once each is given to the pellet its limiter meets, without
// repeats: a pellet meets a limiter only if no pellet lies between them.
void met_limiters(const Model& model, const InstantContacts& c, std::vector<LimiterContact>& met) {
  met.clear();
  for (const LimiterContact& contact : c.limiters) {
    const int pellet = meets_limiter(contact, c, model);
    const LimiterContact m{pellet, contact.limiter, contact.side};
    if (pellet >= 0 && std::find(met.begin(), met.end(), m) == met.end()) met.push_back(m);
  }
}

// No contacts yet, for n pellets (the storage kept).
void no_contacts(int n, InstantContacts& c) {
  c.limiters.clear();
  c.pairs.clear();
  c.parting.clear();
  c.pellets.assign(n, PelletAtInstant{});
}

// The crossings with the limiter arrivals first, each part in its order.
void limiters_first(const MotionInterval& interval, const std::vector<Crossing>& crossings,
                    std::vector<Crossing>& ordered) {
  ordered.clear();
  auto arrival = [&](const Crossing& x) {
    return interval.watches()[x.watch].kind == WatchKind::limiter;
  };
  for (const Crossing& x : crossings)
    if (arrival(x)) ordered.push_back(x);
  for (const Crossing& x : crossings)
    if (!arrival(x)) ordered.push_back(x);
}

}  // namespace

void snap(const Model& model, const EventTolerances& tol, const MotionInterval& interval,
          const std::vector<Crossing>& crossings, const std::vector<Neighbours>& neighbours,
          const std::vector<bool>& armed, Vec& y, InstantWorkspace& ws) {
  InstantContacts& c = ws.contacts;
  no_contacts(model.size(), c);
  // One set of radii for the whole instant, from the angles before any snap.
  const PlaceRadii radii = place_radii(tol, y);
  std::vector<bool>& at_limiter = ws.at_limiter;
  on_limiters(model, radii, interval.bodies(), armed, y, at_limiter);
  // Arrivals at limiters first: a pellet that meets one arriving at the same instant meets it on
  // the limiter's angle, not halfway.
  limiters_first(interval, crossings, ws.ordered);
  for (const Crossing& crossing : ws.ordered)
    snap_crossing(model, interval, crossing, y, at_limiter, c);
  add_standing(model, tol, radii, interval, neighbours, y, c.limiters);
  frontmost(model, radii, neighbours, c.limiters, y, ws.limiters);
  std::swap(c.limiters, ws.limiters);
  for (const LimiterContact& lc : c.limiters) at_limiter[lc.pellet] = true;
  kept_apart(model, neighbours, c.limiters, armed, ws.apart);
  ws.before_touching = y;
  snap_touching(y, neighbours, radii.contact, at_limiter, ws.apart, c.pairs);
  add_snapped_on_angle(model, radii, armed, ws.before_touching, y, c.limiters);
  add_body_pairs(interval.bodies(), c.pairs);
  met_limiters(model, c, ws.limiters);
  std::swap(c.limiters, ws.limiters);
}

InstantContacts snap(const Model& model, const EventTolerances& tol, const MotionInterval& interval,
                     const std::vector<Crossing>& crossings,
                     const std::vector<Neighbours>& neighbours, const std::vector<bool>& armed,
                     Vec& y) {
  InstantWorkspace ws;
  snap(model, tol, interval, crossings, neighbours, armed, y, ws);
  return std::move(ws.contacts);
}

InstantContacts initial_contacts(const Model& model, const EventTolerances& tol, Vec& y) {
  InstantContacts c;
  no_contacts(model.size(), c);
  for (int i = 0; i < model.size(); ++i) {
    const double phi = y[phi_index(i)];
    for (int l = 0; l < limiter_count(model); ++l) {
      const double d = wrap_angle(phi - model.limiters[l].angle);
      if (!model.limiters[l].acts_on(i) || std::abs(d) > tol.start_on_limiter) continue;
      y[phi_index(i)] = phi - d;
      c.limiters.push_back({i, l, start_side(model, i)});
    }
  }
  return c;
}

}  // namespace vibro
