#include "core/summary.h"

#include <cmath>

namespace vibro {

Summary summarize(const Model& model, const std::vector<Event>& sorted_events) {
  Summary s;
  s.impacts_by_limiter.assign(model.limiters.size(), std::vector<int>(model.size(), 0));
  int impacts = 0;
  for (const Event& e : sorted_events) {
    switch (e.kind) {
      case EventKind::limiter:
        ++s.limiter_impacts;
        ++s.impacts_by_limiter[e.limiter][e.pellets[0]];
        break;
      case EventKind::collision:
        ++s.collisions;
        if (e.limiter >= 0) ++s.limiter_impacts;  // a group's plastic impact into a limiter
        break;
      case EventKind::chatter:
        ++s.chatter_sequences;
        break;
      default:
        continue;  // not an impact
    }
    s.last_impact = {++impacts, e.t};
  }
  return s;
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
