// How to run a simulation: the solver's options (what the driver reads) and, for the convenience
// entry, which outputs to keep.
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "core/integrators/stepper.h"

namespace vibro {

// What the driver (core/run/simulate.h) reads: time span, method, tolerances, the event search
// and the budgets every run answers to. validate_options (core/run/validate.h) checks them.
// How often a run asks SolverOptions::cancelled: rarely enough to cost nothing, often enough to
// stop within a few ms (1024 steps of the paper scene take about 1 ms).
inline constexpr long kCancelPollSteps = 1024;

struct SolverOptions {
  double t_end = 10.0;  // s, > 0
  Method method = Method::automatic;
  double rtol = 1e-9;
  double atol = 1e-12;

  // Every run ends: these bound its work.
  long max_events = 200000;
  long max_steps = 20000000;
  double deadline_ms = std::numeric_limits<double>::infinity();  // wall clock
  // Asked every kCancelPollSteps steps whether the caller wants the run stopped (a Python
  // caller's Ctrl-C); true ends it, Termination::cancelled. None: the run is not cancelled.
  std::function<bool()> cancelled;

  // Dense-output points inside each step where the event search looks at the watches near their
  // roots; a recorded curve keeps at least one more per step, and as many as its turning asks.
  int samples_per_step = 4;
  // Search every step at those points, also where every watch stays far from zero (a calm step,
  // core/events/watch.h): for reference runs that must not share that cut with the runs they judge.
  bool sample_every_step = false;
  // Events before this time are a transient (a sweep's): they count in no limit, and the event
  // log, the path and the Lyapunov exponents start after it.
  double keep_events_from = -std::numeric_limits<double>::infinity();
  // Whether a frictionless sliding body of one pellet (no kinetic nor static friction) has its
  // reversals as events. Its speed's zero changes no equation, so a run that reads no reversal
  // (a sweep's) passes them: the body watches the limiters on both sides of it instead of its
  // reversal and the limiter ahead, its steps are not cut there, and the run's events, path
  // and step counts have none of them (core/events/interval.h).
  bool frictionless_reversals = true;
};

// A scene's run: how to solve it, and what the convenience entry (core/analysis/checked_run.h)
// keeps of it. Each output is an observer of the run (core/run/observers.h).
struct SimOptions : SolverOptions {
  // Check the run against a shadow solution at tighter tolerances (core/analysis/trust.h); off,
  // the trust fields come from the run alone and cannot see event-time errors.
  bool check = true;
  // Branches are kept only for the pellets flagged here (index = pellet), up to record_until.
  std::vector<bool> record;
  double record_until = std::numeric_limits<double>::infinity();
  // The branches' samples kept in all, 0: no bound. Past it the recorder halves its density (every
  // other sample dropped, each branch's ends kept) and keeps one in twice as many from then on:
  // a long run is drawn whole, more coarsely, instead of stopping.
  long max_samples = 0;
  // Times at which the state is kept (RunResult::stops), increasing: a stroboscopic section. Steps
  // land on them, so each state is a step's end, not an interpolation; at an instant, the state
  // after it.
  std::vector<double> stops;
  // From the settle_window-th stop on, the run ends at the first stop where its last
  // settle_window stops have settled (section_settled, core/run/section_period.h;
  // RunResult::settled), instead of at t_end. 0: it goes to t_end.
  int settle_window = 0;
  // Keep the run's hybrid path (RunResult::path): what the variational equations replay.
  bool keep_path = false;
  // At most this many instants of it (about 1 KB each); it ends where they are reached.
  std::size_t path_limit = std::numeric_limits<std::size_t>::max();
  // The Lyapunov exponents of the motion from keep_events_from (or 0) to the end
  // (RunResult::lyapunov, core/analysis/lyapunov.h).
  bool lyapunov = false;
};

}  // namespace vibro
