#include "tests/robustness/scene_runs.h"

#include <gtest/gtest.h>

#include "core/analysis/checked_run.h"
#include "io/scene_json.h"
#include "tests/robustness/run_invariants.h"

namespace vibro::robustness {

Scene parsed(std::string_view text) {
  SceneOrError r = scene_from_text(text);
  if (const FieldError* e = std::get_if<FieldError>(&r)) {
    ADD_FAILURE() << "scene refused: " << e->field << " " << e->message;
    return {};
  }
  return std::get<Scene>(std::move(r));
}

RunResult run_checked(const Scene& scene, const SimOptions& options) {
  RunResult run = simulate(scene.model, options);
  EXPECT_EQ(run_violation(run, scene.model, options.t_end), "");
  return run;
}

RunResult run_checked(const Scene& scene, Method method, double deadline_ms) {
  SimOptions options = scene.sim;
  options.method = method;
  options.deadline_ms = deadline_ms;
  return run_checked(scene, options);
}

}  // namespace vibro::robustness
