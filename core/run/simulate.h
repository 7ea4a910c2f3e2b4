// The event-driven simulation of MODEL.md: integrate each segment between events with the
// chosen method, locate events on the dense output, resolve each event instant, restart.
#pragma once

#include <memory>

#include "core/integrators/stepper.h"
#include "core/model/model.h"
#include "core/run/result.h"
#include "core/run/sim_options.h"

namespace vibro {

// Runs the model from t = 0 to options.t_end. Precondition: validate_model and
// validate_options accept the inputs. Never throws for numerical trouble: the result's
// stats.termination and stats.message say why a run ended early, and no NaN is reported.
RunResult simulate(const Model& model, const SimOptions& options);

// The same with a stepper of the caller's (benchmarks put peer integrators behind the Stepper
// interface); options.method then only names the run in its stats.
RunResult simulate(const Model& model, const SimOptions& options, std::unique_ptr<Stepper> stepper);

}  // namespace vibro
