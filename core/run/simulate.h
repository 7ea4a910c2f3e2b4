// The event-driven simulation of MODEL.md, the driver alone: integrate each motion interval step
// by step, search each step's dense output for the interval's events, resolve the instant of the
// earliest, open the next interval. What the run keeps along the way is up to the observers the
// caller attaches (core/run/observer.h, core/run/observers.h); the checked run of a scene's
// options is core/analysis/checked_run.h.
#pragma once

#include <memory>
#include <span>

#include "core/integrators/stepper.h"
#include "core/model/model.h"
#include "core/run/observer.h"
#include "core/run/result.h"
#include "core/run/sim_options.h"

namespace vibro {

// The stepper the options ask for, its longest step longest_step(model) times `longest_step_scale`
// (a shadow's is shorter: core/analysis/trust.h).
std::unique_ptr<Stepper> make_stepper(const Model& model, const SolverOptions& options,
                                      AutoExplicit auto_explicit = AutoExplicit::by_tolerance,
                                      double longest_step_scale = 1.0);

// Runs the model from t = 0 to options.t_end with the stepper (options.method only names the run
// in its stats), telling the observers, in their order, what happens. The result holds the stats
// (all but the consistency and trust fields) and the earliest graze; the observers fill the rest
// at their on_end. Precondition: validate_model and validate_options accept the inputs. Never
// throws for numerical trouble: stats.termination and stats.message say why a run ended early.
RunResult simulate(const Model& model, const SolverOptions& options, Stepper& stepper,
                   std::span<RunObserver* const> observers);

}  // namespace vibro
