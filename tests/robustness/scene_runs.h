// Helpers for the robustness tests: a scene from JSON text that must parse, and its run with
// the invariants of run_invariants.h checked.
#pragma once

#include <string_view>

#include "core/run/result.h"
#include "io/scene.h"

namespace vibro::robustness {

// The scene in `text`; fails the current test (and returns an empty scene) if it is refused.
Scene parsed(std::string_view text);

// Simulates scene.model with `options` and checks run_violation on the result.
RunResult run_checked(const Scene& scene, const SimOptions& options);
// The same with the scene's options, the given method, and a deadline so no test can hang.
RunResult run_checked(const Scene& scene, Method method, double deadline_ms = 5000.0);

}  // namespace vibro::robustness
