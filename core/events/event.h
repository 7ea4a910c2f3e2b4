// What happens at an event instant, as a run lists it, and a near miss of one: the values the
// event layer hands up to the run (core/run/result.h) and the trust check.
#pragma once

#include <string_view>
#include <vector>

namespace vibro {

enum class EventKind { limiter, collision, reversal, stick, release, chatter };
std::string_view event_kind_name(EventKind kind);  // "limiter", "collision", ...

struct Event {
  double t = 0.0;
  EventKind kind = EventKind::reversal;
  std::vector<int> pellets;         // pellets the event touches, in one order
  int limiter = -1;                 // limiter index for limiter and chatter events, else -1
  double phi = 0.0;                 // unwrapped angle of pellets[0] at the event
  std::vector<double> dphi_before;  // per pellet in `pellets`
  std::vector<double> dphi_after;
  int impacts_resolved = 0;     // chatter: impacts summed in closed form after the listed ones
  double t_accumulation = 0.0;  // chatter: the accumulation time t* (= t, or past t_end)
};

// A near miss: a watch of the motion (a body's speed, a gap, the way to a limiter) that fell to
// a minimum within its error of zero and rose again. Whether its event (a turn, a collision, an
// impact) happens depends on differences below the tolerance: a run and its shadow of one
// method missed a collision that tighter runs found, and vouched for the events after it.
// Or (`order`) a pellet that two impacts closed on at one instant (core/events/impacts.h,
// shared_by_closings): which came first, and with it the outcome, is decided alike.
struct Graze {
  enum class Of { speed, gap, limiter, order };
  Of of = Of::speed;
  int pellet = -1;  // the pellet whose speed or way it is; gap: the one behind; order: the one
                    // both impacts involve
  int other = -1;   // gap: the pellet ahead; limiter: the limiter
  double t = 0.0;   // the minimum
  double earliest = 0.0;  // the earliest its event could come, had the minimum been below zero
  double value = 0.0;     // the watch's value there (rad/s for a speed, rad otherwise)
  double error = 0.0;     // the error it was held against
};

}  // namespace vibro
