#include "core/events/impacts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/events/contacts.h"

namespace vibro {

void collide(double m_i, double m_j, double k_c, double& v_i, double& v_j) {
  const double M = m_i + m_j;
  const double vi = v_i, vj = v_j;
  v_i = ((m_i - k_c * m_j) * vi + m_j * (1.0 + k_c) * vj) / M;
  v_j = ((m_j - k_c * m_i) * vj + m_i * (1.0 + k_c) * vi) / M;
}

bool separated_by_limiter(const Model& model, const std::vector<LimiterContact>& lc,
                          const std::vector<bool>& armed, const PairContact& p) {
  auto touches = [&](int pellet, int limiter, int side) {
    return std::any_of(lc.begin(), lc.end(), [&](const LimiterContact& c) {
      return c.pellet == pellet && c.limiter == limiter && c.side == side;
    });
  };
  for (const LimiterContact& c : lc) {
    if (!armed[c.limiter]) continue;
    const Limiter& l = model.limiters[c.limiter];
    if (c.pellet == p.behind && c.side == -1 && l.acts_on(p.ahead) &&
        !touches(p.ahead, c.limiter, -1))
      return true;
    if (c.pellet == p.ahead && c.side == +1 && l.acts_on(p.behind) &&
        !touches(p.behind, c.limiter, +1))
      return true;
  }
  return false;
}

namespace {

void strike_limiter(const Model& model, std::vector<bool>& armed, int limiter) {
  if (model.limiters[limiter].mobile) armed[limiter] = false;
  for (std::size_t j = 0; j < model.limiters.size(); ++j) {
    if (model.limiters[j].mobile && model.limiters[j].rearm_by == limiter) armed[j] = true;
  }
}

// The impact that takes a group of touching pellets (behind to ahead) from its speeds in y0 to
// the limit of its endless cascade: the group moves with its momentum's speed, and stops if that
// drives it into an armed limiter it touches. None for a group the cascade did not move (a
// pellet resting elsewhere, pellets moving together: their momentum's speed is theirs up to
// round-off), nor for a lone pellet at no limiter.
std::optional<Event> group_limit(const Model& model, const std::vector<int>& members, const Vec& y0,
                                 const std::vector<bool>& armed,
                                 const std::vector<LimiterContact>& lc) {
  double P = 0.0, M = 0.0;
  for (int i : members) {
    P += model.pellets[i].m * y0[dphi_index(i)];
    M += model.pellets[i].m;
  }
  double V = P / M;
  int limiter = -1;
  for (const LimiterContact& c : lc) {
    if (std::find(members.begin(), members.end(), c.pellet) == members.end() || !armed[c.limiter])
      continue;
    if (limiter < 0) limiter = c.limiter;
    if (V * c.side < 0.0) {
      V = 0.0;
      limiter = c.limiter;
    }
  }
  const bool struck = std::any_of(members.begin(), members.end(), [&](int i) {
    return std::abs(y0[dphi_index(i)] - V) >
           8.0 * std::numeric_limits<double>::epsilon() * std::abs(V);
  });
  if (!struck || (members.size() == 1 && limiter < 0)) return std::nullopt;
  Event e;
  e.kind = members.size() > 1 ? EventKind::collision : EventKind::limiter;
  e.pellets = members;
  e.limiter = limiter;
  for (int i : members) {
    e.dphi_before.push_back(y0[dphi_index(i)]);
    e.dphi_after.push_back(V);
  }
  return e;
}

// The limit of an endless cascade from the state y0 and limiters armed0 before it: each group
// of touching pellets (a limiter between two pellets keeps them in two groups) takes its
// group_limit, and its events replace those of the sweeps (from `first` on in `events`). y and
// armed are set to what the limit leaves; each event counts the `impacts` the sweeps resolved
// before the limit was taken.
void plastic_limit(const Model& model, Vec& y, const Vec& y0, std::vector<bool>& armed,
                   const std::vector<bool>& armed0, const std::vector<LimiterContact>& lc,
                   const std::vector<PairContact>& pc, int impacts, std::size_t first,
                   EventList& events) {
  y = y0;
  armed = armed0;
  PelletLinks links(model.size());
  for (const PairContact& p : pc)
    if (!separated_by_limiter(model, lc, armed0, p)) links.link(p);
  events.shrink_to(first);
  for (const std::vector<int>& members : chains(links)) {
    std::optional<Event> e = group_limit(model, members, y0, armed, lc);
    if (!e) continue;
    e->impacts_resolved = impacts;
    for (int i : members) y[dphi_index(i)] = e->dphi_after.front();
    if (e->limiter >= 0) strike_limiter(model, armed, e->limiter);
    events.add() = std::move(*e);
  }
}

// One sweep's limiter impacts, in the contacts' order: each contact whose pellet approaches its
// armed limiter faster than v_eps rebounds with the limiter's k. Returns how many.
int strike_limiters(const Model& model, Vec& y, std::vector<bool>& armed,
                    const std::vector<LimiterContact>& lc, double v_eps, EventList& events) {
  int impacts = 0;
  for (const LimiterContact& c : lc) {
    const Limiter& lim = model.limiters[c.limiter];
    double& v = y[dphi_index(c.pellet)];
    if (!armed[c.limiter] || !lim.acts_on(c.pellet) || v * c.side >= -v_eps) continue;
    Event& e = events.add();
    e.kind = EventKind::limiter;
    e.pellets.push_back(c.pellet);
    e.limiter = c.limiter;
    e.dphi_before.push_back(v);
    v = -lim.k * v;
    e.dphi_after.push_back(v);
    strike_limiter(model, armed, c.limiter);
    ++impacts;
  }
  return impacts;
}

// One sweep's collisions, in the pairs' order: each pair closing faster than v_eps, with no armed
// limiter between them, collides by Newton's law. Returns how many.
int collide_pairs(const Model& model, Vec& y, const std::vector<bool>& armed,
                  const std::vector<LimiterContact>& lc, const std::vector<PairContact>& pc,
                  double v_eps, EventList& events) {
  int impacts = 0;
  for (const PairContact& p : pc) {
    double& vb = y[dphi_index(p.behind)];
    double& va = y[dphi_index(p.ahead)];
    if (vb - va <= v_eps || separated_by_limiter(model, lc, armed, p)) continue;
    Event& e = events.add();
    e.kind = EventKind::collision;
    e.pellets.assign({p.behind, p.ahead});
    e.dphi_before.assign({vb, va});
    collide(model.pellets[p.behind].m, model.pellets[p.ahead].m, model.k_c, vb, va);
    e.dphi_after.assign({vb, va});
    ++impacts;
  }
  return impacts;
}

}  // namespace

int shared_by_closings(const Model& model, const Vec& y, const std::vector<bool>& armed,
                       const std::vector<LimiterContact>& lc, const std::vector<PairContact>& pc,
                       double v_eps, ImpactScratch& scratch) {
  auto v = [&](int i) { return y[dphi_index(i)]; };
  std::vector<int>& closings = scratch.closings;
  closings.assign(model.size(), 0);
  for (const LimiterContact& c : lc)
    if (armed[c.limiter] && model.limiters[c.limiter].acts_on(c.pellet) &&
        v(c.pellet) * c.side < -v_eps)
      ++closings[c.pellet];
  for (const PairContact& p : pc) {
    if (v(p.behind) - v(p.ahead) <= v_eps || separated_by_limiter(model, lc, armed, p)) continue;
    ++closings[p.behind];
    ++closings[p.ahead];
  }
  for (int i = 0; i < model.size(); ++i)
    if (closings[i] > 1) return i;
  return -1;
}

int shared_by_closings(const Model& model, const Vec& y, const std::vector<bool>& armed,
                       const std::vector<LimiterContact>& lc, const std::vector<PairContact>& pc,
                       double v_eps) {
  ImpactScratch scratch;
  return shared_by_closings(model, y, armed, lc, pc, v_eps, scratch);
}

void resolve_impacts(const Model& model, Vec& y, std::vector<bool>& armed,
                     const std::vector<LimiterContact>& limiter_contacts,
                     const std::vector<PairContact>& pair_contacts, const ImpactOptions& options,
                     ImpactScratch& scratch, EventList& events) {
  std::vector<LimiterContact>& lc = scratch.limiters;
  lc.assign(limiter_contacts.begin(), limiter_contacts.end());
  std::sort(lc.begin(), lc.end(), [](const LimiterContact& a, const LimiterContact& b) {
    return a.pellet != b.pellet ? a.pellet < b.pellet : a.limiter < b.limiter;
  });
  std::vector<PairContact>& pc = scratch.pairs;
  pc.assign(pair_contacts.begin(), pair_contacts.end());
  auto place = [&](int i) {
    const double w = std::fmod(y[phi_index(i)], kTwoPi);
    return w < 0.0 ? w + kTwoPi : w;
  };
  // Insertion sort: stable, and the few pairs of an instant need no buffer (std::stable_sort
  // allocates one).
  for (std::size_t k = 1; k < pc.size(); ++k)
    for (std::size_t j = k; j > 0 && place(pc[j].behind) < place(pc[j - 1].behind); --j)
      std::swap(pc[j], pc[j - 1]);
  scratch.y0 = y;
  scratch.armed0 = armed;
  const std::size_t first = events.size();
  int impacts = 0;
  for (int sweep = 0; sweep < options.max_sweeps; ++sweep) {
    const int struck = strike_limiters(model, y, armed, lc, options.v_eps, events);
    const int collided = collide_pairs(model, y, armed, lc, pc, options.v_eps, events);
    if (struck + collided == 0) return;
    impacts += struck + collided;
  }
  plastic_limit(model, y, scratch.y0, armed, scratch.armed0, lc, pc, impacts, first, events);
}

std::vector<Event> resolve_impacts(const Model& model, Vec& y, std::vector<bool>& armed,
                                   const std::vector<LimiterContact>& limiter_contacts,
                                   const std::vector<PairContact>& pair_contacts,
                                   const ImpactOptions& options) {
  ImpactScratch scratch;
  EventList events;
  resolve_impacts(model, y, armed, limiter_contacts, pair_contacts, options, scratch, events);
  return {events.begin(), events.end()};
}

}  // namespace vibro
