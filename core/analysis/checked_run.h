// The run of a scene's options as API.md describes it: the driver (core/run/simulate.h) with the
// outputs the options ask for, the Lyapunov exponents from its path, and the trust check against a
// shadow run through the same driver (core/analysis/trust.h).
#pragma once

#include <memory>

#include "core/integrators/stepper.h"
#include "core/model/model.h"
#include "core/run/result.h"
#include "core/run/sim_options.h"
#include "core/run/simulate.h"

namespace vibro {

// Runs the model from t = 0 to options.t_end, checked unless options.check is off.
// Precondition: validate_model and validate_options accept the inputs. Never throws for numerical
// trouble: the result's stats.termination and stats.message say why a run ended early, and no NaN
// is reported.
RunResult simulate(const Model& model, const SimOptions& options);

// The shadow the trust check runs beside a run of these options (core/analysis/trust.h): the
// scene moved by check_model, solved as check_options says, within deadline_ms of wall clock.
RunResult run_shadow(const Model& model, const SimOptions& options, double deadline_ms);

// The same with a stepper of the caller's (benchmarks put peer integrators behind the Stepper
// interface), unchecked; options.method then only names the run in its stats.
RunResult simulate(const Model& model, const SimOptions& options, std::unique_ptr<Stepper> stepper);

}  // namespace vibro
