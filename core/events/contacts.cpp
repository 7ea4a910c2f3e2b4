#include "core/events/contacts.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/model/dynamics.h"

namespace vibro {

std::vector<Neighbours> circular_neighbours(const Vec& y, int n) {
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto place = [&](int i) {
    const double w = std::fmod(y[phi_index(i)], kTwoPi);
    return w < 0.0 ? w + kTwoPi : w;
  };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return place(a) < place(b); });
  std::vector<Neighbours> neighbours;
  for (int k = 0; k < n; ++k) {
    const int behind = order[k], ahead = order[(k + 1) % n];
    const double raw = y[phi_index(ahead)] - y[phi_index(behind)];
    double gap = std::fmod(raw, kTwoPi);
    if (gap <= 0.0) gap += kTwoPi;
    neighbours.push_back({behind, ahead, gap - raw});
  }
  return neighbours;
}

void snap_touching(Vec& y, const std::vector<Neighbours>& neighbours, double contact,
                   std::vector<bool>& at_limiter, const std::vector<PairContact>& apart,
                   std::vector<PairContact>& pairs) {
  for (std::size_t pass = 0; pass <= neighbours.size(); ++pass) {
    bool changed = false;
    for (const Neighbours& nb : neighbours) {
      if (std::any_of(apart.begin(), apart.end(), [&](const PairContact& c) {
            return c.behind == nb.behind && c.ahead == nb.ahead;
          }))
        continue;
      double& pb = y[phi_index(nb.behind)];
      double& pa = y[phi_index(nb.ahead)];
      const double gap = pa - pb + nb.offset;
      const bool listed = std::any_of(pairs.begin(), pairs.end(), [&](const PairContact& c) {
        return c.behind == nb.behind && c.ahead == nb.ahead;
      });
      // A pair already in contact stays at one place, however far an earlier snap of this
      // loop moved one of them (onto a pellet at a limiter).
      if (!listed && gap > contact) continue;
      if (!listed) pairs.push_back({nb.behind, nb.ahead});
      if (gap == 0.0) continue;
      if (at_limiter[nb.ahead]) {
        pb = pa + nb.offset;
        at_limiter[nb.behind] = true;
      } else {
        pa = pb - nb.offset;
        at_limiter[nb.ahead] = at_limiter[nb.behind];
      }
      changed = true;
    }
    if (!changed) break;
  }
}

namespace {

// Each chain of the links in turn, into the empty vector `next()` returns: the chains in the
// order of their pellets' lowest index, each behind to ahead.
template <class Next>
void for_each_chain(const PelletLinks& links, std::vector<bool>& placed, Next next) {
  const int n = links.size();
  placed.assign(n, false);
  for (int start = 0; start < n; ++start) {
    if (placed[start]) continue;
    int first = start;
    for (int guard = 0; links.behind(first) >= 0 && links.behind(first) != start && guard < n;
         ++guard)
      first = links.behind(first);
    std::vector<int>& members = next();
    for (int i = first, guard = 0; i >= 0 && !placed[i] && guard < n; i = links.ahead(i), ++guard) {
      members.push_back(i);
      placed[i] = true;
    }
  }
}

}  // namespace

std::vector<std::vector<int>> chains(const PelletLinks& links) {
  std::vector<std::vector<int>> out;
  std::vector<bool> placed;
  for_each_chain(links, placed, [&]() -> std::vector<int>& { return out.emplace_back(); });
  return out;
}

void chains_as_bodies(const PelletLinks& links, std::vector<bool>& placed,
                      std::vector<Body>& bodies) {
  std::size_t count = 0;
  for_each_chain(links, placed, [&]() -> std::vector<int>& {
    if (count == bodies.size()) bodies.emplace_back();
    Body& body = bodies[count++];
    std::vector<int> members = std::move(body.members);
    body = Body{};
    body.members = std::move(members);
    body.members.clear();
    return body.members;
  });
  bodies.resize(count);
}

namespace {

// Force (N), mass (kg) and momentum (kg·rad/s) of a chain of touching pellets, and the side of
// an armed limiter one of its pellets touches (0: none).
struct Chain {
  double F = 0.0, M = 0.0, P = 0.0;
  double D = 0.0;  // Σ m_i c_i, kg/s: its dampers' force per unit speed over R
  double damping() const { return D / M; }  // 1/s
  int limiter_side = 0;
};

// What join_touching reads of the instant: the model, the time, the state and the limiters.
struct JoinScene {
  const Model& model;
  double t;  // s
  const Vec& y;
  const std::vector<LimiterContact>& limiter_contacts;
  const std::vector<bool>& armed;
};

// The chain from `from` (included) in direction `way` (+1 ahead, −1 behind) along the links.
Chain chain_from(const JoinScene& s, const PelletLinks& links, int from, int way) {
  const int n = s.model.size();
  Chain c;
  for (int i = from, guard = 0; i >= 0 && guard < n; i = links.next(i, way), ++guard) {
    c.F += s.model.pellets[i].force.at(s.t);
    c.M += s.model.pellets[i].m;
    c.D += s.model.pellets[i].m * s.model.pellets[i].c;
    c.P += s.model.pellets[i].m * s.y[dphi_index(i)];
    for (const LimiterContact& l : s.limiter_contacts)
      if (l.pellet == i && s.armed[l.limiter]) c.limiter_side = l.side;
  }
  return c;
}

// The acceleration (rad/s²) of a chain at rest at phi, given what holds it: static friction up
// to its capacity, and a limiter at its back (side +1 stops it going down, −1 going up).
double held_acceleration(const Model& model, const Chain& c, double phi) {
  const double a = c.F / (c.M * model.R) - model.g / model.R * std::sin(phi);
  const double capacity = stick_capacity(model, phi);
  const double up = std::max(a - capacity, 0.0), down = std::min(a + capacity, 0.0);
  return (c.limiter_side > 0 ? 0.0 : down) + (c.limiter_side < 0 ? 0.0 : up);
}

// How fast the chain behind closes on the chain ahead, rad/s². Moving at one speed, friction
// and gravity per mass are the same for both: the forces and dampers per mass decide. At rest
// (speed within v_merge), what holds each decides; one at rest and one moving (parting from a
// pellet that a limiter stopped): each one's own acceleration.
double relative_acceleration(const Model& model, const SlidingLaw& law, const Chain& b,
                             const Chain& a, double phi, double v_merge) {
  const double vb = b.P / b.M, va = a.P / a.M;
  const bool rest_b = std::abs(vb) <= v_merge, rest_a = std::abs(va) <= v_merge;
  if (!rest_b && !rest_a)
    return (b.F / b.M - a.F / a.M) / model.R - (b.damping() * vb - a.damping() * va);
  auto own = [&](const Chain& c, double v, bool rest) {
    return rest ? held_acceleration(model, c, phi)
                : law.acceleration({c.F, c.M, c.damping()}, std::cos(phi), std::sin(phi), v,
                                   v > 0.0 ? 1 : -1);
  };
  return own(b, vb, rest_b) - own(a, va, rest_a);
}

// Whether chains approaching at `approach` (rad/s) and pressed together at `press` (rad/s²)
// move on as one. Parting at w and pressed back at p, they meet again after 2w/p, and at k_c·w
// after that: the whole chatter lasts 2w/(p(1 − k_c)). They part by w²/(2p) at most, a gap that
// round-off alone may close or open.
bool move_as_one(double approach, double press, double k_c, const JoinCriteria& criteria) {
  const double chatter = 2.0 * std::abs(approach) / (press * (1.0 - k_c));
  const double flight = approach * approach / (2.0 * press);
  return press >= 0.0 && (std::abs(approach) <= criteria.v_merge ||
                          chatter <= criteria.chatter_time || flight <= criteria.flight);
}

}  // namespace

void join_touching(const Model& model, const SlidingLaw& law, double t, const Vec& y,
                   const std::vector<PairContact>& pairs,
                   const std::vector<LimiterContact>& limiter_contacts,
                   const std::vector<bool>& armed, const JoinCriteria& criteria,
                   JoinScratch& scratch, std::vector<Body>& bodies) {
  const JoinScene scene{model, t, y, limiter_contacts, armed};
  PelletLinks& links = scratch.links;
  links.reset(model.size());
  // Chains grow until nothing more joins: a pair's press depends on the chains behind and ahead.
  for (bool grew = true; grew;) {
    grew = false;
    for (const PairContact& p : pairs) {
      if (links.ahead(p.behind) >= 0 || links.behind(p.ahead) >= 0) continue;
      if (separated_by_limiter(model, limiter_contacts, armed, p)) continue;
      const Chain b = chain_from(scene, links, p.behind, -1);
      const Chain a = chain_from(scene, links, p.ahead, +1);
      const double approach = b.P / b.M - a.P / a.M;
      const double phi = y[phi_index(p.behind)];
      const double press = relative_acceleration(model, law, b, a, phi, criteria.v_merge);
      if (move_as_one(approach, press, model.k_c, criteria)) {
        links.link(p);
        grew = true;
      }
    }
  }
  chains_as_bodies(links, scratch.placed, bodies);
}

std::vector<Body> join_touching(const Model& model, double t, const Vec& y,
                                const std::vector<PairContact>& pairs,
                                const std::vector<LimiterContact>& limiter_contacts,
                                const std::vector<bool>& armed, const JoinCriteria& criteria) {
  JoinScratch scratch;
  std::vector<Body> bodies;
  join_touching(model, SlidingLaw(model), t, y, pairs, limiter_contacts, armed, criteria, scratch,
                bodies);
  return bodies;
}

}  // namespace vibro
