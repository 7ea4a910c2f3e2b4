// The event functions of one segment (MODEL.md, "Events"); their roots are found by
// core/events/crossing_finder.h. Each watch is a scalar g(t) that is positive while nothing
// happens; its event is the first time g falls to zero or below after having been positive.
#pragma once

#include <optional>
#include <vector>

#include "core/events/event.h"
#include "core/integrators/ode.h"
#include "core/model/dynamics.h"
#include "core/model/model.h"
#include "core/model/motion.h"

namespace vibro {

enum class WatchKind {
  reversal,    // s·dphi of a sliding body
  limiter,     // side·(target − phi): the next armed limiter angle on one side of a sliding
               // body (side = s: ahead of it; a body that passes its reversals also watches the
               // one behind it, side = −s)
  gap,         // distance from one body's leading pellet to the next body's trailing pellet
  release,     // static capacity − |free acceleration| of a stuck body (or, resting: pull away)
  separation,  // sliding: compression between two parts; held: the margin before a part is
               // pulled off
  normal,      // bilateral law: the normal force's sign times its value at the start; where
               // it crosses zero, friction's |N| has a kink, at which the integration restarts
};

struct Watch {
  WatchKind kind;
  int body = -1;     // reversal, limiter, release, separation: the body
  int pellet = -1;   // the pellet whose state is read (a body's leader; gap: the one behind)
  int other = -1;    // gap: the pellet ahead
  int limiter = -1;  // limiter: the limiter hit
  // limiter: angle to reach; gap: the constant winding offset; normal: ±1; release: the
  // round-off the stick test allows the capacity (EventTolerances::accel_round_off·(1 + |φ|)),
  // so that a body held exactly at its threshold starts positive and is let go as it leaves it.
  double target = 0.0;
  int side = 0;   // limiter: +1 for an angle above phi, −1 below it
  int split = 0;  // separation: members [0, split) behind, [split, n) ahead
  // A watch that starts on its own root (two pellets that just collided touch) is watched
  // deflated: order 1, (g(t) − g(t0)) / (t − t0), which starts at g'(t0) > 0 when they part;
  // order 2, where it also starts flat (a plastic collision leaves them at one speed),
  // (g(t) − g(t0)) / (t − t0)², which starts at g''(t0)/2. A quick return within one step is
  // then still found.
  int deflation = 0;
  double t0 = 0.0, g0 = 0.0, start = 0.0;
};

double evaluate(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
                const Vec& y);
// Whether the finder follows a watch between samples, and tracks its near misses: one of the
// motion (a body's speed, a gap, the way to a limiter), whose rate the state gives; not the
// thresholds of forces (release, separation, normal), which depend on time alone or on a kink.
inline bool follows_motion(WatchKind kind) {
  return kind == WatchKind::reversal || kind == WatchKind::gap || kind == WatchKind::limiter;
}
// For a watch of the motion: its raw value less its value where a deflated watch started (the
// event is where this reaches zero), and its rates of change.
struct Closing {
  double value = 0.0;
  double rate = 0.0;
  double curvature = 0.0;  // the second derivative, where the state gives it (not a speed's)
  // The time from here to where the quadratic these give meets zero, if it closes on it:
  // curving toward zero, a gap that is still opening is pressed shut again.
  double time_to_zero() const;
  // Whether that time is shorter than span (> 0): the same answer from the quadratic's value at
  // span, with no square root (asked at every sample of every step).
  bool meets_within(double span) const {
    if (!(value >= 0.0) || (value == 0.0 && !(rate > 0.0))) return true;
    // Concave, the quadratic falls below zero past its one positive root and stays there.
    if (curvature < 0.0) return value + span * (rate + 0.5 * curvature * span) < 0.0;
    return rate < 0.0 && value + rate * span < 0.0;
  }
};
// The curvature costs the bodies' accelerations: asked for where it matters (an interval's start,
// a march); between samples, the rates' difference stands in for it.
Closing closing(const Watch& w, const Model& model, const SlidingLaw& law,
                const std::vector<Body>& bodies, double t, const Vec& y,
                bool with_curvature = false);
// The body pellet `pellet` belongs to (every pellet is in one).
const Body& body_of(const std::vector<Body>& bodies, int pellet);
// The watch's own value, not deflated.
double raw_value(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
                 const Vec& y);
// A watch of time alone: release and separation follow the forces on a body whose place does not
// change (held, or moving as one), so g(t) is a sum of cosines. At t, `rate` is |dg/dt| and
// `curvature` bounds |d²g/dt²| everywhere: g(t + Δ) ≥ g(t) − rate·Δ − curvature·Δ²/2.
struct TimeBounds {
  double rate = 0.0;
  double curvature = 0.0;
};
// Not a sliding body's separation whose parts are damped differently per unit mass: the dampers'
// difference follows the body's speed.
bool depends_on_time_alone(const Watch& w, const Model& model, const std::vector<Body>& bodies);
// For the separation watch of a held body, at its crossing: the part pulled off, +1 the part
// ahead of the cut, −1 the part behind; 0 for a sliding body (its parts slide on apart).
int pulled_off(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
               const Vec& y);
// For a release watch at its crossing: the way the body goes, ±1 (away from the limiter it rests
// on; the way the force pulls a stuck body).
int release_direction(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
                      const Vec& y);
TimeBounds time_bounds(const Watch& w, const Model& model, const std::vector<Body>& bodies,
                       double t);

// Makes w watch its deflated form from (t0, y0), where dg/dt is `rate` and d²g/dt² `accel`:
// of order 1, or of order 2 where the rate is 0.
void deflate(Watch& w, const Model& model, const std::vector<Body>& bodies, double t0,
             const Vec& y0, double rate, double accel);

// Whether phi lies within near of the limiter angle theta (mod 2π): the test next_limiter
// excludes a limiter by, so a body either touches a limiter or watches it, never neither.
bool on_limiter_angle(double theta, double phi, double near);

// The next armed limiter angle ahead of phi in direction s that acts on any of the body's
// members, farther than `from` (rad) that way: s·(angle − phi) > from; returns false if there
// is none. With from = near it skips a limiter the body touches; with from = −near it finds it.
bool next_limiter(const Model& model, const std::vector<bool>& armed, const Body& body, double phi,
                  int s, double from, int& limiter, double& target);

// A root of one watch inside a step.
struct Crossing {
  int watch;
  double t;
};

// A watch that is a linear function of the state, g(y) = Σ weight·y[index] + constant (before
// its deflation): reversal, limiter and gap. On a step given as polynomials its polynomial is the
// same sum of the state's (core/events/crossing_finder.h); null for the others.
struct LinearForm {
  int terms = 0;
  int index[2] = {0, 0};
  double weight[2] = {0.0, 0.0};
  double constant = 0.0;
};
std::optional<LinearForm> linear_form(const Watch& w, const std::vector<Body>& bodies);

}  // namespace vibro
