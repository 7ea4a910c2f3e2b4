// The time and state of an event found on a step's dense output, brought to the steps' accuracy.
#pragma once

#include "core/events/interval.h"
#include "core/events/watch.h"
#include "core/integrators/ode.h"
#include "core/integrators/stepper.h"
#include "core/model/dynamics.h"
#include "core/model/model.h"

namespace vibro {

// A root found on a dense output of lower order than the steps (every method's) errs by that
// order. One step to the root of the watch's quadratic at the precise state brings the time to
// the steps' accuracy, and the state moves to it by the midpoint rule: both then err by the
// correction's cube, unless the watch turns within ten corrections (a pellet that turns back at
// the limiter), where the dense root stands (tests/core/polish_test.cpp).
//
// The rate and curvature are the watch's own at the precise state where the state gives them (a
// watch of the motion), else differences on the dense output over a thousandth of the way from
// the step's start, where a deflated watch starts: over a larger share, a short flight inside a
// long step takes its slope from the watch before its start.
class RootPolisher {
 public:
  explicit RootPolisher(const Model& model) : model_(model), law_(model) {}

  // The crossing c found at t in the step [a, b] of the interval; y is the dense state at t.
  // Moves t and y to the corrected root, or leaves them where no correction stays in the step.
  void polish(const MotionInterval& interval, const Crossing& c, Stepper& stepper, double a,
              double b, double& t, Vec& y);

 private:
  const Model& model_;
  const SlidingLaw law_;  // for the rates of the watches of the motion
  Vec scratch_;           // states and rates while polishing
  Vec midpoint_rate_;     // the rate that moves the state to the root
};

}  // namespace vibro
