// How to run a simulation: time span, solver, limits, and what to record.
#pragma once

#include <limits>
#include <vector>

#include "core/integrators/stepper.h"

namespace vibro {

struct SimOptions {
  double t_end = 10.0;  // s, > 0
  Method method = Method::automatic;
  double rtol = 1e-9;
  double atol = 1e-12;
  // Which explicit method `auto` runs (core/integrators/stepper.h): the trust check's shadow of an
  // `auto` run sets the other one.
  AutoExplicit auto_explicit = AutoExplicit::by_tolerance;
  // Check the run against a shadow solution at tighter tolerances (core/analysis/trust.h); off,
  // the trust fields come from the run alone and cannot see event-time errors.
  bool check = true;
  // The longest step, as a share of longest_step(model) (core/model/dynamics.h): the check's shadow
  // takes shorter ones, so that where that bound holds the steps it does not share the run's.
  double longest_step_scale = 1.0;

  // Every run ends: these bound its work.
  long max_events = 200000;
  long max_steps = 20000000;
  double deadline_ms = std::numeric_limits<double>::infinity();  // wall clock

  // Branches are kept only for the pellets flagged here (index = pellet), up to record_until.
  std::vector<bool> record;
  double record_until = std::numeric_limits<double>::infinity();
  // Dense-output points inside each step where the event search looks at the watches near their
  // roots; a recorded curve keeps at least one more per step, and as many as its turning asks.
  int samples_per_step = 4;
  // Search every step at those points, also where every watch stays far from zero (a calm step,
  // core/events/watch.h): for reference runs that must not share that cut with the runs they judge.
  bool sample_every_step = false;
  // The branches' samples kept in all, 0: no bound. Past it the recorder halves its density (every
  // other sample dropped, each branch's ends kept) and keeps one in twice as many from then on:
  // a long run is drawn whole, more coarsely, instead of stopping.
  long max_samples = 0;
  // Times at which the state is kept (RunResult::stops), increasing: a stroboscopic section. Steps
  // land on them, so each state is a step's end, not an interpolation; at an instant, the state
  // after it.
  std::vector<double> stops;
  // Events before this time are not kept (a sweep's transient): a long run's memory is then its
  // record's. They count in no limit and no summary; the trust check compares the kept ones.
  double keep_events_from = -std::numeric_limits<double>::infinity();
  // Keep the run's hybrid path (RunResult::path): what the variational equations replay.
  bool keep_path = false;
  // At most this many instants of it (about 1 KB each); it ends where they are reached.
  std::size_t path_limit = std::numeric_limits<std::size_t>::max();
  // The Lyapunov exponents of the motion from keep_events_from (or 0) to the end
  // (RunResult::lyapunov, core/analysis/lyapunov.h).
  bool lyapunov = false;
};

}  // namespace vibro
