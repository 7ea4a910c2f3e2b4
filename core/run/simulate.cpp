#include "core/run/simulate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "core/events/contacts.h"
#include "core/events/crossing_finder.h"
#include "core/events/event_tolerances.h"
#include "core/events/instant.h"
#include "core/events/watch.h"
#include "core/run/polish.h"
#include "core/run/run_state.h"

namespace vibro {
namespace {

// The driver's loop over motion intervals; RunState (core/run/run_state.h) holds what it reads
// and the bookkeeping around it.
class Simulation : RunState {
 public:
  using RunState::RunState;
  RunResult run();

 private:
  // Resolves an instant at t and tells the observers; its outcome is instant_.outcome.
  void instant(double t, const std::vector<Body>& before, const InstantContacts& contacts,
               const Vec* unsnapped);
  // Opens the interval of the last instant's bodies, taken from instant_.outcome (which gets the
  // storage of the interval's previous bodies back).
  void open_interval(double t);
  // Integrates the open interval until its first event (true) or t_end or a stop (false).
  bool integrate_to_event(double& t, std::vector<Crossing>& found);
  // Settles the landings the last step passed before t (a polynomial step's,
  // Stepper::step_landing), each from its dense output; true, with t the landing, where an
  // observer ended the run at one.
  bool settle_passed_landings(double& t);
  // The step's first crossings, searched on its dense output (first: its first sample searched).
  std::vector<Crossing> search_step(double a, double b, int& first);

  std::optional<MotionInterval> interval_;
  CrossingFinder finder_;
  RootPolisher polisher_{model_};
  const SlidingLaw law_{model_};
  InstantWorkspace instant_;  // the instants' contacts, outcome and scratch
  Vec unsnapped_;             // the state before an instant's snap
  Vec y_before_;              // the state an instant starts from, snapped
};

void Simulation::instant(double t, const std::vector<Body>& before, const InstantContacts& contacts,
                         const Vec* unsnapped) {
  y_before_ = y_;
  resolve_instant(model_, unsnapped ? tol_ : start_tol_, law_, t, before, contacts, y_, armed_,
                  instant_);
  const InstantOutcome& out = instant_.outcome;
  note_instant(t, out);
  const InstantView view{t,          unsnapped,   y_before_,          before, out.events.view(),
                         out.bodies, out.touched, out.kinetic_change, y_};
  for (RunObserver* o : observers_) o->on_instant(view);
}

void Simulation::open_interval(double t) {
  if (interval_)
    interval_->reopen(instant_.outcome.bodies, armed_, neighbours_, t, y_, tol_);
  else
    interval_.emplace(model_, std::move(instant_.outcome.bodies), armed_, neighbours_, t, y_, tol_,
                      !opt_.frictionless_reversals);
  if (smooth_)
    stepper_.continue_smoothly(interval_->dynamics(), t, y_);
  else
    stepper_.start(interval_->dynamics(), t, y_);
  finder_.start(interval_->watches(), model_, interval_->bodies(), t, y_, opt_.rtol, opt_.atol);
  for (RunObserver* o : observers_) o->on_interval(t, y_, *interval_);
}

std::vector<Crossing> Simulation::search_step(double a, double b, int& first) {
  const int m = static_cast<int>(times_.size()) - 1;
  const MotionInterval& in = *interval_;
  times_[m] = b;
  states_[m] = stepper_.y();
  // Samples inside the step for the watches near their roots; a step where every watch stays
  // far from zero, or where the stepper's polynomials serve every watch, is searched at its end
  // alone.
  const bool alone = finder_.served_by_polynomials(in.watches(), in.bodies(), stepper_) ||
                     (!opt_.sample_every_step &&
                      finder_.calm(in.watches(), model_, in.bodies(), a, b, states_[m]));
  first = alone ? m : 0;
  for (int k = 0; k < m; ++k) times_[k] = a + (b - a) * (k + 1) / (m + 1);
  for (int k = first; k < m; ++k) stepper_.dense(times_[k], states_[k]);
  return finder_.find(in.watches(), model_, in.bodies(), stepper_,
                      std::span<const double>(times_).subspan(first),
                      std::span<const Vec>(states_).subspan(first), tol_.simultaneous(b));
}

bool Simulation::settle_passed_landings(double& t) {
  for (double land = land_; land < t;) {
    stepper_.dense(land, y_);
    settled(land, interval_->bodies());
    if (ended_) {  // the step ends here
      t = land;
      for (RunObserver* o : on_step_end_) o->on_step_end(t, y_, *interval_, false);
      return true;
    }
    const double next = next_landing();
    if (!(next > land)) break;  // an observer that does not move on
    land = next;
  }
  return false;
}

bool Simulation::integrate_to_event(double& t, std::vector<Crossing>& found) {
  const MotionInterval& in = *interval_;
  while (!stopped_ && !ended_ && t < opt_.t_end) {
    if (!take_step(t)) return false;
    const double a = stepper_.t_prev(), b = stepper_.t();
    int first = 0;
    found = search_step(a, b, first);
    const bool event = !found.empty();
    const double first_event = event ? found.front().t : std::numeric_limits<double>::infinity();
    const StepSamples step{a, b, y_, times_, states_, first, first_event, stepper_};
    for (RunObserver* o : on_step_) o->on_step(step);
    t = event ? found.front().t : b;
    if (land_ < t && settle_passed_landings(t)) return false;
    if (event) {
      stepper_.dense(t, y_);
      polisher_.polish(in, found.front(), stepper_, a, b, t, y_);
    } else {
      y_ = stepper_.y();
    }
    for (RunObserver* o : on_step_end_) o->on_step_end(t, y_, in, event);
    if (!event) settled(t, in.bodies());
    if (!std::isfinite(y_.sum())) {
      fail(t, Termination::numerical_failure, "the state became non-finite");
      return false;
    }
    if (event) return true;
    if (over_budget(t)) return false;
  }
  return false;
}

RunResult Simulation::run() {
  for (RunObserver* o : observers_) o->on_start(y_);
  double t = 0.0;
  const InstantContacts start = initial_contacts(model_, tol_, y_);
  instant(0.0, initial_bodies(model_, y_), start, nullptr);
  // The last instant's bodies (until an interval takes them).
  const std::vector<Body>& bodies = instant_.outcome.bodies;
  settled(0.0, bodies);
  bool opened = false;  // the last instant's bodies went to an interval
  std::vector<Crossing> found;
  while (!stopped_ && !ended_ && t < opt_.t_end) {
    open_interval(t);
    opened = true;
    if (interval_->at_rest_for_good()) {
      t = opt_.t_end;
      settled(t, interval_->bodies());
      break;
    }
    if (!integrate_to_event(t, found) || !advances(t)) break;
    interval_->align_directions(y_);
    unsnapped_ = y_;
    snap(model_, tol_, *interval_, found, neighbours_, armed_, y_, instant_);
    instant(t, interval_->bodies(), instant_.contacts, &unsnapped_);
    opened = false;
    settled(t, bodies);
    over_budget(t);
  }
  if (!stopped_ && !ended_)
    t = std::max(t, opt_.t_end);
  else if (!std::isfinite(y_.sum()))
    y_ = stepper_.y();  // the last finite state
  const bool at_rest = opened && interval_->at_rest_for_good();
  const std::vector<Body>& last = opened ? interval_->bodies() : bodies;
  const MotionInterval* open = interval_ ? &*interval_ : nullptr;
  const EndView end{t, std::min(t, opt_.t_end), y_, last, open, stopped_, ended_, at_rest};
  return finish(end, finder_.first_graze());
}

}  // namespace

RunResult simulate(const Model& model, const SolverOptions& options, Stepper& stepper,
                   std::span<RunObserver* const> observers) {
  return Simulation(model, options, stepper, observers).run();
}

}  // namespace vibro
