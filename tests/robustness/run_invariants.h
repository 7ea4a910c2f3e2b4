// The contract every run keeps, however hostile its scene (core/run/simulate.h, io/result_json.h):
// finite numbers, events in time order inside the run, an early stop that names its time, and
// no NaN or infinity in the JSON. Shared by the robustness tests and the fuzz target.
#pragma once

#include <string>

#include "core/model/model.h"
#include "core/run/result.h"

namespace vibro::robustness {

// The first invariant `run` breaks, in words; empty when it keeps them all.
std::string run_violation(const RunResult& run, const Model& model, double t_end);

}  // namespace vibro::robustness
