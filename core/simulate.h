// The event-driven simulation of MODEL.md: integrate each segment between events with the
// chosen method, locate events on the dense output, resolve each event instant, restart.
#pragma once

#include "core/model.h"
#include "core/result.h"
#include "core/sim_options.h"

namespace vibro {

// Runs the model from t = 0 to options.t_end. Precondition: validate_model and
// validate_options accept the inputs. Never throws for numerical trouble: the result's
// stats.termination and stats.message say why a run ended early, and no NaN is reported.
RunResult simulate(const Model& model, const SimOptions& options);

}  // namespace vibro
