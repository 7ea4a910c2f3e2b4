// What a run reports along the way goes to observers the caller attaches (as Boost.Odeint's
// integrate functions take an observer): the driver (core/run/simulate.h) knows a stepper and
// its observers, and each output (recording, section stops, the hybrid path, the event log, the
// energy balance: core/run/observers.h) is one of them. Observers only read what the driver
// hands them, except that one may ask steps to land on a time (landing()).
#pragma once

#include <limits>
#include <span>
#include <type_traits>
#include <vector>

#include "core/events/event.h"
#include "core/events/interval.h"
#include "core/integrators/ode.h"
#include "core/integrators/stepper.h"
#include "core/model/motion.h"
#include "core/run/result.h"

namespace vibro {

// An event instant at t, resolved: the state reached it as `unsnapped` (null at the run's start,
// where nothing is snapped), was snapped onto its events as `y_before`, and leaves it as `y_after`.
struct InstantView {
  double t = 0.0;
  const Vec* unsnapped = nullptr;
  const Vec& y_before;
  const std::vector<Body>& bodies_before;
  // What happened, in order, at their own times (a chatter may accumulate past t_end).
  std::span<const Event> events;
  const std::vector<Body>& bodies_after;
  const std::vector<bool>& touched;  // per pellet: an event ended its motion interval
  double kinetic_change = 0.0;       // J: what the impacts changed
  const Vec& y_after;
};

// One accepted step over [a, b], before the state moves to its end (or to its event at t_event):
// the event search's samples and the stepper's dense output over it.
struct StepSamples {
  double a = 0.0, b = 0.0;
  const Vec& y_a;  // the state at a
  // The search's times inside the step and b last; states[k] holds the state at times[k] for k
  // from `first_searched` (a calm step is searched at its end alone).
  std::span<const double> times;
  std::span<const Vec> states;
  int first_searched = 0;
  double t_event = std::numeric_limits<double>::infinity();  // the step's first event, if any
  const Stepper& stepper;                                    // dense(t, out) over [a, b]
};

// How the run ended, for on_end.
struct EndView {
  double t = 0.0;          // where the loop stopped (t_end or later if it completed)
  double t_reached = 0.0;  // min(t, t_end)
  const Vec& y;            // the last (finite) state
  // The bodies of the last instant, or of the interval that ran to the end.
  const std::vector<Body>& bodies;
  const MotionInterval* interval = nullptr;  // the last one opened, if any
  bool stopped = false;                      // a budget or a failure ended it, before t_end
  bool ended = false;                        // an observer ended it, before t_end (ends_run)
  bool at_rest_for_good = false;             // the last interval ran to the end at rest
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  // The run starts at t = 0 from y0, before the instant at the start.
  virtual void on_start(const Vec& /*y0*/) {}
  // After each instant (the start's too).
  virtual void on_instant(const InstantView& /*instant*/) {}
  // A motion interval opens at t from y.
  virtual void on_interval(double /*t*/, const Vec& /*y*/, const MotionInterval& /*interval*/) {}
  // A time steps must land on (> the current time), or infinity. A polynomial step
  // (StepView::polynomials) passes it instead, its state there as exact as at its end: the
  // driver then settles that state (on_settled) before the step's end.
  virtual double landing() const { return std::numeric_limits<double>::infinity(); }
  // Each accepted step, before its end (see StepSamples): cheap unless it asks for dense output.
  virtual void on_step(const StepSamples& /*step*/) {}
  // The state y at a step's end t, or at its first event (`at_event`), in the interval.
  virtual void on_step_end(double /*t*/, const Vec& /*y*/, const MotionInterval& /*interval*/,
                           bool /*at_event*/) {}
  // The state at t is settled with these bodies: the start, a step's end without an event, a
  // landing a polynomial step passed before its first event, after an instant, and a rest to
  // the end.
  virtual void on_settled(double /*t*/, const Vec& /*y*/, const std::vector<Body>& /*bodies*/) {}
  // Whether the observer has what the run is for, so that the run ends at the state it has just
  // been told of (on_settled), before t_end: asked after each settled state.
  virtual bool ends_run() const { return false; }
  // The run ended: the observer hands what it kept to the result (whose stats the driver filled).
  virtual void on_end(const EndView& /*end*/, RunResult& /*result*/) {}

  // Which of the calls made at every step the observer overrides: the driver makes those calls
  // to these observers alone (a no-op call at each of a run's steps costs a few per cent of a
  // short-stepped run). An observer that does not say gets them all.
  struct PerStep {
    bool landing = true, step = true, step_end = true, settled = true;
  };
  virtual PerStep per_step() const { return {}; }
};

// What observer type O overrides of the per-step calls, read from its declarations: &O::f names
// RunObserver's member where O does not declare its own f.
template <class O>
constexpr RunObserver::PerStep per_step_of() {
  return {
      .landing = !std::is_same_v<decltype(&O::landing), decltype(&RunObserver::landing)>,
      .step = !std::is_same_v<decltype(&O::on_step), decltype(&RunObserver::on_step)>,
      .step_end = !std::is_same_v<decltype(&O::on_step_end), decltype(&RunObserver::on_step_end)>,
      .settled = !std::is_same_v<decltype(&O::on_settled), decltype(&RunObserver::on_settled)>};
}

}  // namespace vibro
