// Impacts at one instant (MODEL.md, events 2, 3 and 5): limiter impacts and pellet collisions,
// processed pairwise in a deterministic order until nothing approaches. A cascade that does not
// settle in a few sweeps (a light pellet squeezed between a heavy one and a limiter) is resolved
// as its limit, one plastic impact of the touching group, in bounded work.
#pragma once

#include <vector>

#include "core/events/event.h"
#include "core/events/event_list.h"
#include "core/integrators/ode.h"
#include "core/model/model.h"
#include "core/model/motion.h"

namespace vibro {

// Pellet `pellet` touches limiter `limiter` from `side` (+1: it lies on the phi > angle side).
struct LimiterContact {
  int pellet;
  int limiter;
  int side;
  bool operator==(const LimiterContact&) const = default;
};

// Pellets `behind` and `ahead` (next in +phi order) are at the same place.
struct PairContact {
  int behind;
  int ahead;
  bool operator==(const PairContact&) const = default;
};

// Two pellets on the two sides of an armed limiter that acts on both do not touch each other:
// one of them touches the limiter from its own side (the one behind from below, −1, or the one
// ahead from above, +1), so the other, next to it across the limiter's angle, is on the far side
// unless it touches the limiter from that same side too.
bool separated_by_limiter(const Model& model, const std::vector<LimiterContact>& limiter_contacts,
                          const std::vector<bool>& armed, const PairContact& pair);

// Newton's law with momentum conserved, velocities signed along phi (MODEL.md, event 3).
void collide(double m_i, double m_j, double k_c, double& v_i, double& v_j);

struct ImpactOptions {
  int max_sweeps = 16;  // beyond this a cascade is taken to its plastic limit
  // Approach speeds up to this are resting contacts, not impacts, rad/s: pellets that touch
  // after a plastic impact approach at round-off (1e-22 rad/s), which is no event.
  double v_eps = 0.0;
};

// The pellet shared by two contacts of an instant that both approach before any of its impacts
// (two pairs, or a pair and a limiter), or -1. Their impacts' order decides the outcome, and
// both came within the contact radius of their roots: which was first is decided by times below
// that radius over the approach speed (up to 2e-9 s at 0.05 rad/s), so a run and its shadow can
// both take the wrong order
// (tests/differential/corpus/ill-conditioned-pellet-closed-on-from-both-sides-at-one-instant.json).
int shared_by_closings(const Model& model, const Vec& y, const std::vector<bool>& armed,
                       const std::vector<LimiterContact>& limiter_contacts,
                       const std::vector<PairContact>& pair_contacts, double v_eps);

// What resolve_impacts and shared_by_closings reuse from one instant to the next (sized by the
// model's pellets and an instant's contacts), so that they allocate nothing once sized.
struct ImpactScratch {
  std::vector<LimiterContact> limiters;  // the contacts in the order they are resolved
  std::vector<PairContact> pairs;
  Vec y0;                     // the state before the impacts
  std::vector<bool> armed0;   // the limiters armed before them
  std::vector<int> closings;  // per pellet: the contacts closing on it
};
int shared_by_closings(const Model& model, const Vec& y, const std::vector<bool>& armed,
                       const std::vector<LimiterContact>& limiter_contacts,
                       const std::vector<PairContact>& pair_contacts, double v_eps,
                       ImpactScratch& scratch);

// Resolves the impacts among the contacts on the state y (core/model/motion.h): its speeds are
// updated in place, its angles order the pair contacts (by increasing phi mod 2π) and are left
// as they are. `armed` holds every limiter's state and is updated (a mobile limiter is disarmed
// by the impact it takes; an impact re-arms the limiters whose rearm_by names the struck one).
// Returns the impacts as events without time or angle (the caller fills those in).
std::vector<Event> resolve_impacts(const Model& model, Vec& y, std::vector<bool>& armed,
                                   const std::vector<LimiterContact>& limiter_contacts,
                                   const std::vector<PairContact>& pair_contacts,
                                   const ImpactOptions& options = {});
// The same, the impacts appended to `events`.
void resolve_impacts(const Model& model, Vec& y, std::vector<bool>& armed,
                     const std::vector<LimiterContact>& limiter_contacts,
                     const std::vector<PairContact>& pair_contacts, const ImpactOptions& options,
                     ImpactScratch& scratch, EventList& events);

}  // namespace vibro
