#include "core/run/summary.h"

#include <algorithm>
#include <cmath>

namespace vibro {
namespace {

bool is_impact(const Event& e) {
  return e.kind == EventKind::limiter || e.kind == EventKind::collision ||
         e.kind == EventKind::chatter;
}

}  // namespace

Summary summarize(const Model& model, const std::vector<Event>& sorted_events) {
  Summary s;
  s.impacts_by_limiter.assign(model.limiters.size(), std::vector<int>(model.size(), 0));
  int impacts = 0;
  for (const Event& e : sorted_events) {
    if (!is_impact(e)) continue;
    if (e.kind == EventKind::limiter) {
      ++s.limiter_impacts;
      ++s.impacts_by_limiter[e.limiter][e.pellets[0]];
    } else if (e.kind == EventKind::collision) {
      // Also a group's plastic stop against the limiter it names (a cascade's limit): one
      // impact, counted once.
      ++s.collisions;
    } else {
      ++s.chatter_sequences;
    }
    s.last_impact = {++impacts, e.t};
  }
  return s;
}

bool ends_vibro_impact(const std::vector<Event>& sorted_events, double t_reached, bool completed,
                       bool at_rest_for_good) {
  double last = 0.0, longest_spell = 0.0;
  bool any = false;
  for (const Event& e : sorted_events) {
    if (!is_impact(e)) continue;
    longest_spell = std::max(longest_spell, e.t - last);
    last = e.t;
    any = true;
  }
  if (!any || at_rest_for_good) return true;
  return completed && t_reached - last > 3.0 * longest_spell;
}

std::vector<FinalState> final_states(const Model& model, const std::vector<Body>& bodies,
                                     const Vec& y) {
  std::vector<FinalState> out(model.size());
  for (const Body& b : bodies) {
    for (int i : b.members) {
      FinalState& f = out[i];
      f.phi = y[phi_index(i)];
      f.dphi = y[dphi_index(i)];
      f.state = b.mode == Mode::sliding ? PelletState::sliding
                : b.mode == Mode::stuck ? PelletState::stuck
                                        : PelletState::resting_at_limiter;
      f.limiter = b.mode == Mode::resting ? b.limiter : -1;
      if (!std::isfinite(f.phi) || !std::isfinite(f.dphi)) f = FinalState{};
    }
  }
  return out;
}

}  // namespace vibro
