// Who touches whom around the circle: neighbours and their gaps, pellets close enough to touch
// at an instant, and which touching pellets move on together as one body.
#pragma once

#include <vector>

#include "core/events/impacts.h"
#include "core/integrators/ode.h"
#include "core/model/dynamics.h"
#include "core/model/model.h"
#include "core/model/motion.h"

namespace vibro {

// Two pellets next to each other around the circle; their gap phi_ahead − phi_behind + offset
// lies in [0, 2π] for the whole run, because pellets never pass each other.
struct Neighbours {
  int behind;
  int ahead;
  double offset;
};

// The neighbours of n pellets (n ≥ 2) in their circular order at the state y.
std::vector<Neighbours> circular_neighbours(const Vec& y, int n);

// Neighbours closer than `contact` (rad) touch at this instant too: they are added to `pairs` and
// snapped onto one place (the one at a limiter stays put, and one snapped onto it is at the
// limiter too). Pairs listed in `apart` (a limiter between them) never touch. An inelastic
// cascade among several pellets closes their gaps geometrically, and only treating the
// near-touching ones together ends it in bounded work (and never lets round-off push one pellet
// through another).
// `at_limiter` (per pellet) is updated: a pellet snapped onto one at a limiter is at it too.
void snap_touching(Vec& y, const std::vector<Neighbours>& neighbours, double contact,
                   std::vector<bool>& at_limiter, const std::vector<PairContact>& apart,
                   std::vector<PairContact>& pairs);

// Pellets linked into chains of touching ones: for each pellet, its neighbour behind and ahead in
// its chain, −1 at a chain's ends.
class PelletLinks {
 public:
  explicit PelletLinks(int n = 0) : links_(n) {}
  // n pellets, none linked (the storage kept).
  void reset(int n) { links_.assign(n, Link{}); }
  int size() const { return static_cast<int>(links_.size()); }
  void link(const PairContact& p) {
    links_[p.behind].ahead = p.ahead;
    links_[p.ahead].behind = p.behind;
  }
  int behind(int i) const { return links_[i].behind; }
  int ahead(int i) const { return links_[i].ahead; }
  // The next pellet from i in direction `way` (+1 ahead, −1 behind), or −1.
  int next(int i, int way) const { return way > 0 ? ahead(i) : behind(i); }

 private:
  struct Link {
    int behind = -1;
    int ahead = -1;
  };
  std::vector<Link> links_;
};

// The chains, each behind to ahead, in the order of their pellets' lowest index; every pellet
// in one. A closed ring starts at the pellet ahead of its lowest index.
std::vector<std::vector<int>> chains(const PelletLinks& links);
// The same chains as the members of `bodies`, one body each, their other fields at Body's
// defaults; the bodies' storage is reused. `placed`: scratch.
void chains_as_bodies(const PelletLinks& links, std::vector<bool>& placed,
                      std::vector<Body>& bodies);

// When touching pellets move on as one body: their forces press them together, and they would
// otherwise collide again at once — equal speeds within `v_merge`, a remaining chatter between
// them shorter than `chatter_time` (its plastic limit), or a flight apart within the round-off
// of the gap (`flight`).
struct JoinCriteria {
  double v_merge = 0.0;       // rad/s
  double chatter_time = 0.0;  // s
  double flight = 0.0;        // rad
};

// The bodies after an instant, members in +φ order (modes are left to the caller). Pairs on the
// two sides of an armed limiter that acts on both never join.
std::vector<Body> join_touching(const Model& model, double t, const Vec& y,
                                const std::vector<PairContact>& pairs,
                                const std::vector<LimiterContact>& limiter_contacts,
                                const std::vector<bool>& armed, const JoinCriteria& criteria);
// What join_touching reuses from one instant to the next.
struct JoinScratch {
  PelletLinks links;
  std::vector<bool> placed;  // per pellet
};
// The same, written into `bodies` (their storage reused).
void join_touching(const Model& model, const SlidingLaw& law, double t, const Vec& y,
                   const std::vector<PairContact>& pairs,
                   const std::vector<LimiterContact>& limiter_contacts,
                   const std::vector<bool>& armed, const JoinCriteria& criteria,
                   JoinScratch& scratch, std::vector<Body>& bodies);

}  // namespace vibro
