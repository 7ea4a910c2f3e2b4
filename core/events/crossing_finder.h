// The crossing finder: the first root of every watch of a motion interval over each step of the
// integration (MODEL.md, "Events"), and the near misses (Graze) that make an event's order
// uncertain at the run's tolerance.
//
// Per step and per watch it runs four phases, each a function returning the bracket of a root it
// finds (a Bracket: the watch positive at lo, at or below zero at hi):
//   scan     the step's samples: a sign change; for a watch of time alone, steps its bounds prove
//            safe (scan_between); for a watch of the motion, a root its rates predict between
//            samples (march) or a minimum below zero between a closing and an opening sample
//            (minimum_between), which also reports a near miss above zero;
//   refine   Brent's method on the bracket, to round-off of t;
//   recheck  at the earliest crossing every other armed watch must still be positive; one that
//            is not dipped below zero between samples: its bracket from its last positive sample;
//   graze    the near misses before the earliest crossing, and a crossing that may as well have
//            been a turn (or a turn that may as well have struck).
//
// A step is presented through StepView (core/integrators/step_view.h). Where the stepper gives
// the step as polynomials, a watch linear in the state (linear_form) is not scanned: its
// polynomial's first root is isolated between its turning points (core/events/polynomial_roots.h)
// and its minima are the near misses, unless a bound of the polynomial over the step keeps it
// above any near miss; refine and recheck then run on the same dense output.
// A new watch kind adds its value (raw_value), its rate if it is a watch of the motion (closing)
// and, if linear in the state, its linear_form, all in core/events/watch.cpp; the finder does not
// change.
#pragma once

#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "core/events/event.h"
#include "core/events/watch.h"
#include "core/integrators/ode.h"
#include "core/integrators/step_view.h"
#include "core/model/dynamics.h"
#include "core/model/model.h"
#include "core/model/motion.h"

namespace vibro {

// The bracket of one root: g(lo) > 0 >= g(hi), lo < hi.
struct Bracket {
  double lo = 0.0, hi = 0.0;
  double g_lo = 0.0, g_hi = 0.0;
};

// What the finder knows of one watch from the interval's start to the last sample.
struct WatchTrack {
  double last = 0.0;     // its value at the last sample
  Closing closing;       // a watch of the motion: its closing at the last sample
  bool armed = false;    // positive at some sample: only then is its fall to zero an event
  double largest = 0.0;  // a watch of the motion: its largest value (a speed's scale)
  // What calm() found for the step that ends at CrossingFinder::calm_end_: whether the watch stays
  // far from zero over it, and its value and closing at the step's end.
  bool calm = false;
  double end_value = 0.0;
  Closing end_closing;
  // The watch as a linear function of the state (linear_form), fixed for the interval.
  std::optional<LinearForm> form;
  // `closing` is the interval start's without its curvature, which costs the bodies'
  // accelerations and is read only by a scan's first prediction (CrossingFinder::scan takes it
  // then); a step served by polynomials replaces it unread.
  bool curvature_pending = false;
};

// One watch of the interval with what its value depends on: the function the phases search.
struct WatchFunction {
  const Watch& watch;
  const Model& model;
  const std::vector<Body>& bodies;
  const SlidingLaw& law;

  double value(double t, const Vec& y) const { return evaluate(watch, model, bodies, t, y); }
  Closing closing_at(double t, const Vec& y, bool with_curvature = false) const {
    return closing(watch, model, law, bodies, t, y, with_curvature);
  }
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

  // Whether every watch of the step is served by its polynomial (on_polynomials): the step is
  // given as polynomials and each watch is linear in the state and armed. Then `find` needs no
  // samples inside the step: its end alone, with no calm() before it. (The watches' linear
  // forms were taken from the bodies at start(); `bodies` is kept for the callers.)
  bool served_by_polynomials(const std::vector<Watch>& watches, const std::vector<Body>& bodies,
                             const StepView& step);

  // The step (step.t_prev(), times.back()] with the states at the sample times (increasing, the
  // last one the step's end, step.t()). Allocates only when it finds a crossing or a near miss.
  std::vector<Crossing> find(const std::vector<Watch>& watches, const Model& model,
                             const std::vector<Body>& bodies, const StepView& step,
                             std::span<const double> times, std::span<const Vec> states,
                             double simultaneous);

 private:
  // The samples of one step: the previous step's end, then (times, states); `judged`: calm()
  // has judged this step, so its end values stand in the tracks.
  struct Samples {
    double t_prev;
    std::span<const double> times;
    std::span<const Vec> states;
    bool judged;
  };
  struct WatchBracket {
    int watch;
    Bracket bracket;
  };

  // Phase scan: the first root of one watch over the samples, updating its track up to it.
  std::optional<Bracket> scan(WatchTrack& track, const WatchFunction& fn, const StepView& step,
                              const Samples& s);
  // Between the samples (t_a, track.last) and (t_b, y_b, g_b) of an armed watch: a sign change,
  // a root of a watch of time alone, or one its closing at t_a predicts before t_b.
  std::optional<Bracket> crossed(const WatchTrack& track, const WatchFunction& fn,
                                 const StepView& step, double t_a, double t_b, const Vec& y_b,
                                 double g_b);
  // A watch of the motion that turned from closing (track.closing at t_a) to opening (`now` at
  // t_b): a root at its minimum (minimum_between). Completes `now` (its curvature from the rates'
  // difference, but a speed's) and the watch's largest value.
  std::optional<Bracket> turned(WatchTrack& track, const WatchFunction& fn, const StepView& step,
                                double t_a, double t_b, double g_b, Closing& now);

  // The first root of a watch of time alone between two samples (t_a, g_a > 0) and (t_b, g_b),
  // bracketed by steps that its bounds prove safe: a force may beat friction for less than a
  // sample's spacing, or several times between two samples.
  std::optional<Bracket> scan_between(const WatchFunction& fn, const Vec& y, double t_a, double g_a,
                                      double t_b, double g_b) const;
  // From t, closing as `c` says, a crossing before t_end that the samples stepped over.
  std::optional<Bracket> march(const WatchFunction& fn, const StepView& step, double t, Closing c,
                               double t_end);
  // The minimum of a watch between two samples where it turned from closing (a) to opening (b),
  // located on the dense output where its rate is zero: below zero, the bracket of a crossing
  // the samples stepped over; above it, a near miss if it is one (kept in grazes_).
  std::optional<Bracket> minimum_between(const WatchFunction& fn, double largest,
                                         const StepView& step, double t_a, const Closing& a,
                                         double t_b, const Closing& b);
  // A watch linear in the state on a step given as polynomials: the first root of its
  // polynomial, its minima above zero as near misses; nullopt in `served` when the step or the
  // watch cannot be served so (then it is scanned). Without a root, the watch's value and rate
  // at the step's end are its polynomial's.
  std::optional<Bracket> on_polynomials(WatchTrack& track, const WatchFunction& fn,
                                        const StepView& step, bool& served);

  // Phase refine: the root in a bracket to round-off of t, on the dense output.
  double refine(const WatchFunction& fn, const StepView& step, const Bracket& b);
  // Phase recheck: an armed watch that is not positive at `earliest` (state y_at): the bracket
  // from its last positive sample before it.
  std::optional<Bracket> recheck(const WatchFunction& fn, const StepView& step, const Samples& s,
                                 double earliest, const Vec& y_at);
  void recheck_all(const std::vector<Watch>& watches, const Model& model,
                   const std::vector<Body>& bodies, const StepView& step, const Samples& s,
                   std::vector<Crossing>& found, double& earliest);
  // Phase graze: the near misses of the step before its earliest crossing, and the crossings
  // at it that are within the tolerance of a turn.
  void keep_grazes(const std::vector<Watch>& watches, const Model& model,
                   const std::vector<Body>& bodies, const StepView& step,
                   const std::vector<Crossing>& found, double earliest);
  // The step's near misses before `earliest`.
  void keep_near_misses(double earliest);
  void keep(const Graze& g);

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

  std::vector<WatchTrack> tracks_;                              // one per watch of the interval
  double calm_end_ = std::numeric_limits<double>::quiet_NaN();  // the step calm() judged
  double t_start_ = 0.0, rtol_ = 0.0, atol_ = 0.0;
  std::optional<SlidingLaw> law_;  // the model's, for the rates of speeds
  std::optional<Graze> first_graze_;
  // Kept between steps to avoid allocation: the brackets and near misses of a step, and dense
  // states while refining roots.
  std::vector<WatchBracket> brackets_;
  std::vector<Graze> grazes_;
  Vec scratch_, scratch_left_, at_;
  Vec y_start_;  // the state at the interval's start, for a pending curvature
};

}  // namespace vibro
