// Runs made up for the render tests, independent of the simulator: damped pendulums between two
// limiters, integrated with a fixed-step RK4, with reversals, limiter impacts and collisions
// recorded the way core/ reports them (branches between events, events in time order).
#pragma once

#include "core/model/model.h"
#include "core/run/result.h"

namespace vibro::testing {

// Two pellets, limiters at π/4 (mobile, limiter 1) and −π/2 (limiter 2).
Model synthetic_model();

// Integrates `model` (gravity, linear damping `damping` 1/s, no friction) to t_end with both
// pellets recorded. Branches end at reversals and impacts.
RunResult synthetic_run(const Model& model, double t_end, double damping = 0.4);

}  // namespace vibro::testing
