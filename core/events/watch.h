// The event functions of one segment and their root finding on the dense output (MODEL.md,
// "Events"). Each watch is a scalar g(t) that is positive while nothing happens; its event is
// the first time g falls to zero or below after having been positive.
#pragma once

#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "core/events/event.h"
#include "core/integrators/ode.h"
#include "core/model/dynamics.h"
#include "core/model/model.h"
#include "core/model/motion.h"

namespace vibro {

enum class WatchKind {
  reversal,    // s·dphi of a sliding body
  limiter,     // s·(target − phi): the next armed limiter angle ahead of a sliding body
  gap,         // distance from one body's leading pellet to the next body's trailing pellet
  release,     // static capacity − |free acceleration| of a stuck body (or, resting: pull away)
  separation,  // sliding: compression between two parts; held: the margin before a part is
               // pulled off
  normal,      // bilateral law: the normal force's sign times its value at the start; where
               // it crosses zero, friction's |N| has a kink, at which the integration restarts
};

struct Watch {
  WatchKind kind;
  int body = -1;        // reversal, limiter, release, separation: the body
  int pellet = -1;      // the pellet whose state is read (a body's leader; gap: the one behind)
  int other = -1;       // gap: the pellet ahead
  int limiter = -1;     // limiter: the limiter hit
  double target = 0.0;  // limiter: angle to reach; gap: the constant winding offset; normal: ±1
  int split = 0;        // separation: members [0, split) behind, [split, n) ahead
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
  bool meets_within(double span) const;
};
// The curvature costs the bodies' accelerations: asked for where it matters (an interval's start,
// a march); between samples, the rates' difference stands in for it.
Closing closing(const Watch& w, const Model& model, const SlidingLaw& law,
                const std::vector<Body>& bodies, double t, const Vec& y,
                bool with_curvature = false);
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
bool depends_on_time_alone(const Watch& w);
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
// members, farther than near (rad); returns false if there is none.
bool next_limiter(const Model& model, const std::vector<bool>& armed, const Body& body, double phi,
                  int s, double near, int& limiter, double& target);

// A root of one watch inside a step.
struct Crossing {
  int watch;
  double t;
};

// Finds the first crossing of every watch over samples of each step's dense output (a watch that
// stays far from zero over the step at the step's end alone, the rates of the watches of the
// motion predicting a root inside from both ends), refines the earliest ones with Brent's method
// to round-off, and returns those within `simultaneous` of the earliest, sorted by time.
class CrossingFinder {
 public:
  // At the start of a segment: a watch arms once it is positive, so a segment that starts on
  // an event (g = 0, e.g. right after a reversal) does not find it again.
  // The tolerances tell a near miss (a Graze) from a clear one.
  void start(const std::vector<Watch>& watches, const Model& model, const std::vector<Body>& bodies,
             double t0, const Vec& y0, double rtol, double atol);

  // The earliest near miss of the run so far, if any.
  const std::optional<Graze>& first_graze() const { return first_graze_; }

  // Whether the step (t_prev, t], which ends in the state y, needs no samples inside: judged
  // from both ends, every watch stays farther from its root than it moves in the step (by its
  // change and its rates). Then the step's end alone is searched, and the dense output is built
  // only if that search needs it (a watch turning, a closing prediction that falls inside). On
  // a step that is not calm, the next `find` still skips the samples inside for each watch that
  // is, and reuses the values at the end computed here.
  bool calm(const std::vector<Watch>& watches, const Model& model, const std::vector<Body>& bodies,
            double t_prev, double t, const Vec& y);

  // The step (t_prev, times.back()] with the states at the sample times (increasing, the last
  // one the step's end); `dense(t, y)` evaluates the step's dense output.
  template <class Dense>
  std::vector<Crossing> find(const std::vector<Watch>& watches, const Model& model,
                             const std::vector<Body>& bodies, double t_prev,
                             std::span<const double> times, std::span<const Vec> states,
                             double simultaneous, Dense&& dense);

 private:
  // The first root of a watch of time alone between two samples (t_a, g_a > 0) and (t_b, g_b),
  // bracketed by steps that its bounds prove safe: a force may beat friction for less than a
  // sample's spacing, or several times between two samples. False when there is none.
  bool scan_between(const Watch& w, const Model& model, const std::vector<Body>& bodies,
                    const Vec& y, double t_a, double g_a, double t_b, double g_b, double& lo,
                    double& hi, double& g_lo, double& g_hi) const;

  // The near miss of watch w with a minimum gm at tm and half its second derivative c: one
  // when gm lies within the watch's error (relative to the largest value it had, for a speed).
  // A minimum below zero is that of a crossing (grazing_crossing).
  std::optional<Graze> near_miss(const Watch& w, double tm, double gm, double c, double largest,
                                 const Vec& y) const;
  // A gap or a way to a limiter found closing at t whose approach slows so much (`at` holds its
  // rate and curvature there) that, not stopped, it would turn within its error past zero:
  // whether it strikes at all is decided below the tolerance, as for a near miss on the other
  // side. At rtol 1e-8 the grazing preset struck its limiter at 2.5e-4 rad/s, 3e-9 rad short of
  // its turn, where rtol 1e-9 and a reference at 1e-13 turned away.
  std::optional<Graze> grazing_crossing(const Watch& w, double t, const Closing& at,
                                        const Vec& y) const;
  // The minimum of watch w between two samples where it turned from closing (a) to opening (b),
  // located on the dense output where its rate is zero: below zero, the bracket of a crossing
  // the samples stepped over (true); above it, a near miss if it is one.
  template <class Dense>
  bool minimum_between(const Watch& w, int index, const Model& model,
                       const std::vector<Body>& bodies, double t_a, const Closing& a, double t_b,
                       const Closing& b, Dense& dense, double& lo, double& hi, double& g_lo,
                       double& g_hi, std::vector<Graze>& grazes);

  // From t, closing as `c` says, a crossing before t_end that the samples stepped over: its
  // bracket, or false if there is none.
  template <class Dense>
  bool march(const Watch& w, const Model& model, const std::vector<Body>& bodies, double t,
             Closing c, double t_end, Dense& dense, double& lo, double& hi, double& g_lo,
             double& g_hi);

  std::vector<double> last_;
  std::vector<Closing> closing_;  // of a watch of the motion, at the last sample
  // What calm() found for the step ending at calm_end_: per watch, calm over it, and its value
  // (and closing, for a watch of the motion) at the end.
  double calm_end_ = std::numeric_limits<double>::quiet_NaN();
  std::vector<char> calm_;
  std::vector<double> end_value_;
  std::vector<Closing> end_closing_;
  std::vector<bool> armed_;
  std::vector<double> largest_;  // of a watch of the motion this interval (a speed's scale)
  double t_start_ = 0.0, rtol_ = 0.0, atol_ = 0.0;
  std::optional<SlidingLaw> law_;  // the model's, for the rates of speeds
  std::optional<Graze> first_graze_;
  Vec scratch_, scratch_left_;  // dense states while refining roots, kept to avoid allocation
};

// Brent's root finder on [a, b] with f(a) > 0 >= f(b); returns the smallest bracketing point
// found with f <= 0, to round-off of t.
template <class F>
double brent_root(F&& f, double a, double b, double fa, double fb);

}  // namespace vibro

#include "core/events/watch_inl.h"
