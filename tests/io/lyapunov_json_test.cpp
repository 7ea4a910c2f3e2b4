// A scene's "lyapunov": read, kept through the canonical form, and its run's exponents written
// as API.md's numbers (−infinity, a direction perturbations die in, as null).
#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "io/result_json.h"
#include "io/scene_json.h"
#include "tests/io/orbit_scene.h"

namespace vibro {
namespace {

using nlohmann::json;

TEST(LyapunovJson, ASceneAsksForTheExponentsOfItsRun) {
  json s = testing::impact_oscillator_orbit();
  s["lyapunov"] = true;
  const SceneOrError read = scene_from_json(s);
  ASSERT_TRUE(std::holds_alternative<Scene>(read)) << std::get<FieldError>(read).message;
  EXPECT_TRUE(std::get<Scene>(read).sim.lyapunov);
  EXPECT_EQ(scene_to_json(std::get<Scene>(read))["lyapunov"], true);
  s["lyapunov"] = "yes";
  const SceneOrError bad = scene_from_json(s);
  ASSERT_TRUE(std::holds_alternative<FieldError>(bad));
  EXPECT_EQ(std::get<FieldError>(bad).field, "lyapunov");
  s.erase("lyapunov");
  const SceneOrError plain = scene_from_json(s);
  EXPECT_FALSE(std::get<Scene>(plain).sim.lyapunov);
  EXPECT_FALSE(scene_to_json(std::get<Scene>(plain)).contains("lyapunov"));
}

TEST(LyapunovJson, TheRunsExponentsAreWrittenWithNullForMinusInfinity) {
  RunResult run;
  run.lyapunov = LyapunovSpectrum{{0.21, -std::numeric_limits<double>::infinity()}, 300.0, ""};
  const json j = result_to_json(
      run, std::get<Scene>(scene_from_json(testing::impact_oscillator_orbit())).model);
  EXPECT_EQ(j["lyapunov"]["exponents"][0], 0.21);
  EXPECT_TRUE(j["lyapunov"]["exponents"][1].is_null());
  EXPECT_EQ(j["lyapunov"]["span"], 300.0);
  EXPECT_FALSE(j["lyapunov"].contains("unsupported"));
  EXPECT_FALSE(result_to_json(RunResult{}, Model{}).contains("lyapunov"));
}

}  // namespace
}  // namespace vibro
