#include "core/events/instant.h"

#include <algorithm>
#include <cmath>

#include "core/events/chatter.h"
#include "core/model/dynamics.h"

namespace vibro {
namespace {

double kinetic(const Model& model, int i, double v) {
  return 0.5 * model.pellets[i].m * model.R * model.R * v * v;
}

bool contains(const std::vector<PairContact>& pairs, const PairContact& p) {
  return std::any_of(pairs.begin(), pairs.end(), [&](const PairContact& q) {
    return q.behind == p.behind && q.ahead == p.ahead;
  });
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

// The time of the event, and the angle of its first pellet.
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

// Whether pellet i at phi lies on the angle of limiter l, armed and acting on it.
bool held_on_angle(const Model& model, const PlaceRadii& radii, const std::vector<bool>& armed,
                   int i, int l, double phi) {
  return armed[l] && model.limiters[l].acts_on(i) &&
         on_limiter_angle(model.limiters[l].angle, phi, radii.on_limiter);
}

// The pellets that stay put on a limiter's angle when others meet them at an instant: bodies
// resting against one (moved halfway to meet a pellet the limiter does not stop, a resting pellet
// came off its limiter's angle and later struck the limiter from behind), and pellets on the angle
// of a limiter that holds them (one sliding away after a stop went 9e-14 rad past its limiter);
// with each of them its body, whose members lie at one place (a member the limiter does not stop
// was moved halfway, taking the body off the angle).
std::vector<bool> on_limiters(const Model& model, const PlaceRadii& radii,
                              const std::vector<Body>& bodies, const std::vector<bool>& armed,
                              const Vec& y) {
  const int n = model.size();
  std::vector<bool> on(n, false);
  for (const Body& body : bodies)
    if (body.mode == Mode::resting)
      for (int i : body.members) on[i] = true;
  for (int i = 0; i < n; ++i)
    for (int l = 0; l < static_cast<int>(model.limiters.size()); ++l)
      on[i] = on[i] || held_on_angle(model, radii, armed, i, l, y[phi_index(i)]);
  for (const Body& body : bodies)
    if (std::any_of(body.members.begin(), body.members.end(), [&](int i) { return on[i]; }))
      for (int i : body.members) on[i] = true;
  return on;
}

// The side of limiter l a pellet starting on its angle is on: away from where it moves, or
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
    // On the limiter's other side, however close, it is not between (a pellet reversing 6e-11
    // rad short of a limiter does not shield the one resting on the limiter's far side).
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
    arriving = arriving ||
               (w.kind == WatchKind::limiter && w.body == b && std::abs(w.target - phi) <= near);
  for (int l = 0; l < static_cast<int>(model.limiters.size()); ++l) {
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

// The restitution that a body leaving the fixed limiter it struck at this instant meets at each
// of its next impacts there, or −1 if it has none: a lone pellet's is its limiter's k. A body
// that came in as one (its members at one speed) and whose impacts at this instant stayed among
// its members and the limiter leaves at one fraction of that speed, the same at every impact
// after: the cascade is linear in the speed.
double series_restitution(const Model& model, const Body& body, int limiter, double speed,
                          const std::vector<double>& v_in, const std::vector<Event>& impacts) {
  if (body.members.size() == 1) return model.limiters[limiter].k;
  auto member = [&](int i) {
    return std::find(body.members.begin(), body.members.end(), i) != body.members.end();
  };
  for (const Event& e : impacts)
    if (std::any_of(e.pellets.begin(), e.pellets.end(), member) &&
        !std::all_of(e.pellets.begin(), e.pellets.end(), member))
      return -1.0;
  const double v0 = v_in[body.leader()];
  for (int i : body.members)
    if (v_in[i] != v0) return -1.0;
  return v0 != 0.0 ? -speed / v0 : -1.0;
}

// Phase 4: a body that leaves the fixed limiter it just struck, pressed back so hard that the
// rest of its impacts would last less than the chatter time: one chatter event, at rest.
bool sum_chatter(const Model& model, const EventTolerances& tol, double t, const Body& body,
                 int limiter, double restitution, double& v, double a_free, Vec& y,
                 InstantOutcome& out) {
  const int side = v > 0.0 ? 1 : -1;
  const Limiter& lim = model.limiters[limiter];
  const auto series = chatter_series(model, t, lim.angle, side, std::abs(v), restitution, a_free);
  if (!series || series->t_next / (1.0 - series->r) > tol.chatter_time) return false;
  Event e;
  e.kind = EventKind::chatter;
  e.pellets = body.members;
  e.limiter = limiter;
  e.dphi_before.assign(body.members.size(), v);
  e.dphi_after.assign(body.members.size(), 0.0);
  e.impacts_resolved = series->impacts;
  e.t_accumulation = series->t_star;
  for (int i : body.members) {
    out.kinetic_change -= kinetic(model, i, v);
    y[dphi_index(i)] = 0.0;
    out.touched[i] = true;
  }
  v = 0.0;
  out.events.push_back(stamped(std::move(e), series->t_star, y));
  return true;
}

// Phase 5 for one body moving at v: slide, stick or rest against `support`. A body pulled free
// (±1) by a crossing slides that way whatever the stick test says at the root.
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

// A sliding pellet that no impact touched, whose speed at the instant is within v_eps of zero
// and that does not go on the way it went, reaches zero speed here: another body's reversal
// 6e-11 s before its own found it at 1.6e-13 rad/s, and a run listed the one reversal or the
// other as the step sequence had it. Its speed may have turned already (its root just before
// the instant, which was put a little late): a run going on with it its new way listed the
// reversal nowhere.
bool snapped_to_a_halt(const Body& held, double v, bool touched, const Body& now,
                       const EventTolerances& tol) {
  if (held.mode != Mode::sliding || touched || v == 0.0 || std::abs(v) > tol.v_eps) return false;
  return now.mode != Mode::sliding || now.s != held.s;
}

}  // namespace

InstantContacts snap(const Model& model, const EventTolerances& tol, const MotionInterval& interval,
                     const std::vector<Crossing>& crossings,
                     const std::vector<Neighbours>& neighbours, const std::vector<bool>& armed,
                     Vec& y) {
  const int n = model.size();
  const std::vector<Body>& bodies = interval.bodies();
  const std::vector<Watch>& watches = interval.watches();
  InstantContacts c;
  c.reversed.assign(n, false);
  c.released.assign(n, false);
  c.pulled.assign(n, 0);
  // Pellets on a limiter's angle stay there when others meet them; those found touching one
  // below join them.
  const PlaceRadii radii = place_radii(tol, y);
  std::vector<bool> at_limiter = on_limiters(model, radii, bodies, armed, y);
  // Arrivals at limiters first: a pellet that meets one arriving at the same instant meets it on
  // the limiter's angle, not halfway.
  std::vector<Crossing> ordered = crossings;
  std::stable_partition(ordered.begin(), ordered.end(), [&](const Crossing& x) {
    return watches[x.watch].kind == WatchKind::limiter;
  });
  for (const Crossing& crossing : ordered) {
    const Watch& w = watches[crossing.watch];
    switch (w.kind) {
      case WatchKind::limiter: {
        const Body& b = bodies[w.body];
        const double shift = w.target - y[phi_index(w.pellet)];
        for (int i : b.members) {
          y[phi_index(i)] += shift;
          at_limiter[i] = true;
        }
        y[phi_index(w.pellet)] = w.target;
        const int held = held_member(model, b, w.limiter, -b.s);
        if (held >= 0) c.limiters.push_back({held, w.limiter, -b.s});
        break;
      }
      case WatchKind::reversal:
        for (int i : bodies[w.body].members) {
          y[dphi_index(i)] = 0.0;
          c.reversed[i] = true;
        }
        break;
      case WatchKind::gap: {
        // Onto one place: the pellet at a limiter stays put, else both meet halfway.
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
        break;
      }
      case WatchKind::normal:
        break;  // a kink of the equations, not an event: the next interval starts here
      case WatchKind::release: {
        const int way = release_direction(w, model, bodies, crossing.t, y);
        for (int i : bodies[w.body].members) {
          c.released[i] = true;
          c.pulled[i] = way;
        }
        break;
      }
      case WatchKind::separation: {
        const std::vector<int>& members = bodies[w.body].members;
        for (int i : members) c.released[i] = true;
        c.parting.push_back({members[w.split - 1], members[w.split]});
        const int part = pulled_off(w, model, bodies, crossing.t, y);
        const int n_members = static_cast<int>(members.size());
        for (int k = 0; k < n_members; ++k)
          if ((part > 0 && k >= w.split) || (part < 0 && k < w.split)) c.pulled[members[k]] = part;
        break;
      }
    }
  }
  // Standing contacts: bodies resting on limiters, sliding ones on a limiter's angle, and pellets
  // moving together.
  for (const Body& body : bodies) {
    if (body.mode == Mode::resting) {
      const int held = held_member(model, body, body.limiter, body.side);
      if (held >= 0) c.limiters.push_back({held, body.limiter, body.side});
    }
  }
  for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
    if (bodies[b].mode == Mode::sliding)
      touch_on_angle(model, tol, radii, interval, b, neighbours, y, c.limiters);
  }
  // Two bodies arriving together at a limiter: the limiter meets the frontmost pellet, not the
  // one behind (taken as touching it, that one put the limiter between itself and the body
  // ahead).
  std::vector<LimiterContact> fronts;
  for (LimiterContact lc : c.limiters) {
    for (int guard = 0; guard < n; ++guard) {
      const int q =
          pellet_between(model, radii, neighbours, c.limiters, lc.pellet, lc.limiter, lc.side, y);
      if (q < 0) break;
      lc.pellet = q;
    }
    if (std::find(fronts.begin(), fronts.end(), lc) == fronts.end()) fronts.push_back(lc);
  }
  c.limiters = std::move(fronts);
  for (const LimiterContact& lc : c.limiters) at_limiter[lc.pellet] = true;
  std::vector<PairContact> apart;
  for (const Neighbours& nb : neighbours) {
    const PairContact pair{nb.behind, nb.ahead};
    if (separated_by_limiter(model, c.limiters, armed, pair)) apart.push_back(pair);
  }
  const Vec unsnapped = y;
  snap_touching(y, neighbours, radii.contact, at_limiter, apart, c.pairs);
  // A pellet snapped onto a limiter's angle (onto a pellet there that the limiter does not
  // stop) touches the limiter from the side it came from: without the contact, a cascade at
  // this instant drove it through the limiter.
  for (int i = 0; i < n; ++i) {
    for (int l = 0; l < static_cast<int>(model.limiters.size()); ++l) {
      if (!held_on_angle(model, radii, armed, i, l, y[phi_index(i)]) ||
          held_on_angle(model, radii, armed, i, l, unsnapped[phi_index(i)]))
        continue;
      const int side = wrap_angle(unsnapped[phi_index(i)] - model.limiters[l].angle) > 0.0 ? 1 : -1;
      c.limiters.push_back({i, l, side});
    }
  }
  for (const Body& body : bodies) {
    for (int k = 0; k + 1 < static_cast<int>(body.members.size()); ++k) {
      const PairContact pair{body.members[k], body.members[k + 1]};
      if (!contains(c.pairs, pair)) c.pairs.push_back(pair);
    }
  }
  // A pellet meets a limiter only if no pellet lies between them.
  std::vector<LimiterContact> met;
  for (const LimiterContact& contact : c.limiters) {
    const int pellet = meets_limiter(contact, c, model);
    const LimiterContact m{pellet, contact.limiter, contact.side};
    if (pellet >= 0 && std::find(met.begin(), met.end(), m) == met.end()) met.push_back(m);
  }
  c.limiters = std::move(met);
  return c;
}

InstantContacts initial_contacts(const Model& model, const EventTolerances& tol, Vec& y) {
  const int n = model.size();
  InstantContacts c;
  c.reversed.assign(n, false);
  c.released.assign(n, false);
  c.pulled.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    const double phi = y[phi_index(i)];
    for (int l = 0; l < static_cast<int>(model.limiters.size()); ++l) {
      const double d = wrap_angle(phi - model.limiters[l].angle);
      if (!model.limiters[l].acts_on(i) || std::abs(d) > tol.start_on_limiter) continue;
      y[phi_index(i)] = phi - d;
      c.limiters.push_back({i, l, start_side(model, i)});
    }
  }
  return c;
}

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
  const int n = model.size();
  InstantOutcome out;
  out.touched.assign(n, false);

  // Phase 2: impacts.
  std::vector<double> v(n), place(n);
  for (int i = 0; i < n; ++i) {
    v[i] = y[dphi_index(i)];
    place[i] = y[phi_index(i)];
  }
  const std::vector<double> v_in = v;
  out.unordered = shared_by_closings(model, v, armed, contacts.limiters, contacts.pairs, tol.v_eps);
  std::vector<Event> impacts = resolve_impacts(model, v, armed, contacts.limiters, contacts.pairs,
                                               place, ImpactOptions{.v_eps = tol.v_eps});
  if (std::any_of(impacts.begin(), impacts.end(),
                  [](const Event& e) { return e.impacts_resolved > 0; }))
    out.unordered = -1;
  std::vector<int> struck_limiter_of(n, -1);
  for (int i = 0; i < n; ++i) {
    out.kinetic_change += kinetic(model, i, v[i]) - kinetic(model, i, y[dphi_index(i)]);
    y[dphi_index(i)] = v[i];
  }
  for (const Event& e : impacts) {
    for (int i : e.pellets) out.touched[i] = true;
    if (e.kind == EventKind::limiter) struck_limiter_of[e.pellets[0]] = e.limiter;
    out.events.push_back(stamped(e, t, y));
  }

  // Phase 3: joining.
  std::vector<int> body_before(n);
  for (std::size_t b = 0; b < before.size(); ++b)
    for (int i : before[b].members) body_before[i] = static_cast<int>(b);
  std::vector<PairContact> joinable = contacts.pairs;
  std::erase_if(joinable, [&](const PairContact& p) { return contains(contacts.parting, p); });
  out.bodies = join_touching(model, t, y, joinable, contacts.limiters, armed,
                             {tol.v_merge, tol.chatter_time, place_radii(tol, y).flight_round_off});

  for (Body& body : out.bodies) {
    const int L = body.leader();
    const double phi = y[phi_index(L)];
    const double a_free = body_free_acceleration(model, body, t, phi);
    Support support = support_of(body, contacts, armed);

    // A merge is plastic: the body moves with its momentum's speed, unless that drives it into a
    // limiter holding one of its members, which takes that momentum (a pellet parting from one its
    // limiter had just stopped, joined to it by their quick chatter, dragged it through).
    double P = 0.0, M = 0.0;
    for (int i : body.members) {
      P += model.pellets[i].m * y[dphi_index(i)];
      M += model.pellets[i].m;
    }
    double speed = P / M;
    if (support.limiter >= 0 && speed * support.side < 0.0) speed = 0.0;
    for (int i : body.members)
      out.kinetic_change += kinetic(model, i, speed) - kinetic(model, i, y[dphi_index(i)]);

    // Phase 4: chatter.
    int struck = -1;
    for (int i : body.members) struck = std::max(struck, struck_limiter_of[i]);
    if (std::abs(speed) > tol.v_eps && struck >= 0 && armed[struck]) {
      const int side = speed > 0.0 ? 1 : -1;
      const double k = series_restitution(model, body, struck, speed, v_in, impacts);
      if (k >= 0.0 && sum_chatter(model, tol, t, body, struck, k, speed, a_free, y, out))
        support = {struck, side};
    }

    // Phase 5: modes, and the events that say how the motion changed.
    // The crossing spoke for the pellets it pulled free, as long as no other pellet joined them.
    const int way = contacts.pulled[L];
    const int pulled = std::all_of(body.members.begin(), body.members.end(),
                                   [&](int i) { return contacts.pulled[i] == way; })
                           ? way
                           : 0;
    const double capacity =
        stick_capacity(model, phi) + tol.accel_round_off * (1.0 + std::abs(phi));
    set_mode(body, speed, support, a_free, capacity, pulled, tol);
    if (std::abs(speed) <= tol.v_eps) speed = 0.0;
    for (int i : body.members) y[dphi_index(i)] = speed;

    // A member that reached zero speed (its body was sliding), or one let go from a hold.
    bool reversed = false, released = false;
    int left = -1;  // the limiter a released member rested against
    for (int i : body.members) {
      const Body& held = before[body_before[i]];
      reversed = reversed || contacts.reversed[i] ||
                 snapped_to_a_halt(held, v_in[i], out.touched[i], body, tol);
      if (contacts.released[i] && held.mode != Mode::sliding) {
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
      continue;
    }
    e.pellets = body.members;
    e.dphi_before.assign(body.members.size(), 0.0);
    e.dphi_after.assign(body.members.size(), speed);
    out.events.push_back(stamped(std::move(e), t, y));
    for (int i : body.members) out.touched[i] = true;
  }
  return out;
}

}  // namespace vibro
