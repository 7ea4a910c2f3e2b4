// The driver's state between steps and its bookkeeping (core/run/simulate.cpp runs the loop):
// the state and the limiters armed, the budgets a run answers to, its stats, and the end handed
// to the observers.
#pragma once

#include <algorithm>
#include <chrono>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/events/contacts.h"
#include "core/events/event_tolerances.h"
#include "core/events/instant.h"
#include "core/integrators/stepper.h"
#include "core/model/model.h"
#include "core/run/observer.h"
#include "core/run/result.h"
#include "core/run/sim_options.h"

namespace vibro {

class RunState {
 public:
  RunState(const Model& model, const SolverOptions& options, Stepper& stepper,
           std::span<RunObserver* const> observers);

 protected:
  using Clock = std::chrono::steady_clock;

  // Takes a step no further than t_end and every observer's landing; false (and stopped) if the
  // stepper failed, with t at its last accepted point.
  // Inline, as settled(): the driver calls both at every step.
  bool take_step(double& t) {
    land_ = next_landing();
    const StepStatus status = stepper_.step_landing(opt_.t_end, land_);
    return status == StepStatus::ok || step_failed(t, status);
  }
  // The earliest time an observer asks steps to land on, or infinity.
  double next_landing() const {
    double land = std::numeric_limits<double>::infinity();
    for (const RunObserver* o : landing_) land = std::min(land, o->landing());
    return land;
  }
  // The state y_ at t is settled with these bodies (tells the observers).
  void settled(double t, const std::vector<Body>& bodies) {
    for (RunObserver* o : on_settled_) {
      o->on_settled(t, y_, bodies);
      ended_ = ended_ || o->ends_run();
    }
  }
  // Notes an instant at t: the events it adds to the budget, a smooth restart, an undecided order.
  void note_instant(double t, const InstantOutcome& out);
  // False (and stopped) where instants stop advancing in time: an unresolved Zeno sequence.
  bool advances(double t);
  // True (and stopped) once a budget is spent.
  bool over_budget(double t);
  void fail(double t, Termination why, const std::string& message);
  // The stepper failed with `status`: stopped, with t at its last accepted point; false.
  bool step_failed(double& t, StepStatus status);
  // The stats, the graze and the observers' outputs.
  RunResult finish(const EndView& end, const std::optional<Graze>& graze);

  const Model& model_;
  const SolverOptions& opt_;
  const EventTolerances tol_;
  // At the start the speeds are given, not computed: none is round-off to snap to rest (a pellet
  // started at 50 rad/s on a circle of 1e-300 m, where v_eps is 3e137 rad/s, was put at rest).
  const EventTolerances start_tol_;
  Stepper& stepper_;
  const std::span<RunObserver* const> observers_;
  // Those that take each per-step call (RunObserver::per_step).
  std::vector<RunObserver*> landing_, on_step_, on_step_end_, on_settled_;
  Vec y_;
  std::vector<bool> armed_;
  const std::vector<Neighbours> neighbours_;
  std::vector<double> times_;  // the samples of each step's dense output: times and states
  std::vector<Vec> states_;
  bool stopped_ = false;
  bool ended_ = false;   // an observer ended the run at its last settled state (ends_run)
  bool smooth_ = false;  // the last instant was one of reversals alone
  double land_ = 0.0;    // the landing asked of the last step (next_landing)

 private:
  Stats stats_;
  long events_ = 0;  // those counted in the budget: from opt_.keep_events_from on
  int same_instant_ = 0;
  long since_cancel_poll_ = 0;
  double last_instant_ = -1.0;
  Clock::time_point started_ = Clock::now();
  // The first instant whose impacts' order was decided below the tolerance: the trust ends there.
  std::optional<Graze> unordered_;
};

}  // namespace vibro
