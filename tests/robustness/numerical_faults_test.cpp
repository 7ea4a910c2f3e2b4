// Numerical faults found through real scenes end the run cleanly: termination
// numerical_failure, a message naming the time and the cause, finite output, no crash.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/presets.h"
#include "io/result_json.h"
#include "tests/robustness/scene_runs.h"

namespace vibro::robustness {
namespace {

const std::vector<Method> kMethods = {Method::dopri5, Method::dop853, Method::radau5,
                                      Method::automatic, Method::taylor};

// Runs the scene under each method; each must end with numerical_failure at time `at` (as
// the message prints it) for `cause`.
void expect_failure(const char* text, const std::vector<Method>& methods, const std::string& at,
                    const std::string& cause) {
  const Scene scene = parsed(text);
  for (Method method : methods) {
    SCOPED_TRACE(method_name(method));
    const RunResult run = run_checked(scene, method);
    EXPECT_EQ(run.stats.termination, Termination::numerical_failure);
    EXPECT_NE(run.stats.message.find("stopped at t = " + at + " s: " + cause), std::string::npos)
        << run.stats.message;
  }
}

// F0/(m R) = 2e24 rad/s² presses the pellet onto a limiter until the force turns at t = π/6;
// released there, it moves away faster than any step size above round-off of t can follow.
constexpr const char* kHugeForceAtALimiter = R"({"model": {"R": 0.5, "pellets": [
    {"m": 1e-12, "phi0": 0.5, "F0": 1e12, "Omega": 3}], "limiters": [{"angle": 1, "k": 0.5}]},
    "t_end": 5})";

// The Runge–Kutta methods: the Taylor method follows this release (its series carry the force
// in closed form, and the angle is held relative to its size), strikes the limiter from the
// other side after a turn and ends at rest on it, its own check vouching for the run. `auto` at
// the scene's rtol 1e-9 runs Taylor, and a stiffness probe by DOP853 whose step underflows hands
// the step back to Taylor: it ends as Taylor does.
TEST(NumericalFaults, StepSizeUnderflowIsNamedWithItsTime) {
  expect_failure(kHugeForceAtALimiter, {Method::dopri5, Method::dop853, Method::radau5}, "0.523599",
                 "the step size underflowed");
  for (Method method : {Method::taylor, Method::automatic}) {
    SCOPED_TRACE(method_name(method));
    const RunResult run = run_checked(parsed(kHugeForceAtALimiter), method);
    EXPECT_EQ(run.stats.termination, Termination::completed) << run.stats.message;
  }
}

// Without a limiter the same force swings the pellet to φ = A (1 − cos Ωt), A = F0/(m R Ω²) =
// 2.2e23 rad (gravity is 1e-23 of it). The answer prints that angle as a number, not as a
// multiple of π (which overflowed lround and printed φ = -2305843009213693952π).
constexpr const char* kHugeForce = R"({"model": {"R": 0.5, "pellets": [
    {"m": 1e-12, "phi0": 0, "F0": 1e12, "Omega": 3}]}, "t_end": 5})";

TEST(NumericalFaults, AnswerPrintsAHugeAngleInDecimals) {
  const Scene scene = parsed(kHugeForce);
  const RunResult run = run_checked(scene, Method::dop853);
  ASSERT_EQ(run.stats.termination, Termination::completed) << run.stats.message;
  const double A = 1e12 / (1e-12 * 0.5 * 9.0);
  EXPECT_NEAR(run.summary.final[0].phi, A * (1.0 - std::cos(15.0)), 1e-9 * A);
  const std::string answer = answer_sentence(run, scene.model);
  EXPECT_NE(answer.find("φ = 3.91e+23,"), std::string::npos) << answer;
}

// F0/(m R) overflows to infinity in the first right-hand side.
TEST(NumericalFaults, NonFiniteStateIsNamedWithItsTime) {
  expect_failure(R"({"model": {"R": 1e-300, "pellets": [
      {"m": 1e-300, "phi0": 0, "F0": 1e12, "Omega": 3}]}, "t_end": 5})",
                 kMethods, "0", "the state became non-finite");
}

// g/R = 1e301 and dphi² = 1e14: the Jacobian's entries overflow and Newton cannot converge.
TEST(NumericalFaults, RadauNewtonFailureIsNamedWithItsTime) {
  expect_failure(R"({"model": {"R": 1e-300, "pellets": [{"m": 1, "phi0": 0.1, "dphi0": 1e7}]},
      "t_end": 5})",
                 {Method::radau5}, "0", "the implicit method's Newton iteration failed");
}

// Extreme scenes that the reader accepts. Each ends by any termination, within its deadline,
// with the run's invariants kept (run_checked), under every method.
TEST(NumericalFaults, ExtremeScenesEndCleanlyUnderEveryMethod) {
  const std::vector<const char*> scenes = {
      // forcing at 1e9 rad/s on a tiny, light pellet
      R"({"model": {"R": 1e-9, "pellets": [{"m": 1e-12, "phi0": 0, "dphi0": 1e7, "F0": 1e12,
          "Omega": 1e9}]}, "t_end": 5})",
      // a pellet at 1e7 rad/s on a circle of 1 nm
      R"({"model": {"R": 1e-9, "pellets": [{"m": 0.2, "phi0": 0, "dphi0": 1e7}]}, "t_end": 5})",
      // friction angle a hair below π/2: mu ≈ 1e8
      R"({"model": {"R": 0.5, "alpha0": 1.57079632, "pellets": [{"m": 0.2, "phi0": 1,
          "dphi0": 1e3}]}, "t_end": 5})",
      // the largest gravity and radius
      R"({"model": {"g": 1e4, "R": 1e6, "pellets": [{"m": 1e12, "phi0": 3.1, "dphi0": -1e7}],
          "limiters": [{"angle": 1e4, "k": 1}, {"angle": -1e4, "k": 0}]}, "t_end": 5})",
      // eight pellets 2e-9 rad apart, plastic everywhere, one limiter between them
      R"({"model": {"R": 0.5, "k_c": 0, "pellets": [{"m": 1, "phi0": 0, "dphi0": 5},
          {"m": 1e-6, "phi0": 2e-9, "dphi0": -5}, {"m": 1e6, "phi0": 4e-9}, {"m": 1, "phi0": 6e-9},
          {"m": 1, "phi0": 8e-9, "dphi0": 1e3}, {"m": 1, "phi0": 1e-8}, {"m": 1, "phi0": 1.2e-8},
          {"m": 1, "phi0": 1.4e-8, "dphi0": -1e3}],
          "limiters": [{"angle": 3e-9, "k": 0}]}, "t_end": 5})",
      // static friction far above kinetic, forced at the edge of the friction cone
      R"({"model": {"R": 0.5, "alpha0": 0.3, "mu_s": 1e6, "pellets": [{"m": 0.2, "phi0": 0.3,
          "F0": 1e3, "Omega": 1e3}], "limiters": [{"angle": 0.3, "k": 0.999}]}, "t_end": 5})",
  };
  for (const char* text : scenes) {
    const Scene scene = parsed(text);
    for (Method method : kMethods) {
      SCOPED_TRACE(std::string(method_name(method)) + " " + text);
      const RunResult run = run_checked(scene, method, 500.0);
      EXPECT_LT(run.stats.wall_ms, 5000.0);
    }
  }
}

}  // namespace
}  // namespace vibro::robustness

namespace vibro::robustness {
namespace {

// The start's speeds are the scene's own, not round-off: on a circle of 1e-300 m (v_eps
// 3e137 rad/s) the pellets started at 50 and 6 rad/s were reported at rest when the run failed.
TEST(NumericalFaults, ARunFailingAtItsStartReportsTheStartsSpeeds) {
  nlohmann::json paper = nlohmann::json::parse(*preset_json("paper"));
  paper["model"]["R"] = 1e-300;
  const Scene scene = parsed(paper.dump());
  // DOPRI5 takes the first steps (the pellets reach 1e150 rad/s, strike and come to rest).
  for (Method method : {Method::dop853, Method::radau5, Method::automatic}) {
    SCOPED_TRACE(method_name(method));
    const RunResult run = run_checked(scene, method);
    EXPECT_EQ(run.stats.termination, Termination::numerical_failure);
    EXPECT_EQ(run.stats.t_reached, 0.0);
    ASSERT_EQ(run.summary.final.size(), 2u);
    EXPECT_DOUBLE_EQ(run.summary.final[0].dphi, 50.0);
    EXPECT_NEAR(run.summary.final[1].dphi, 6.0, 1e-12);
  }
}

}  // namespace
}  // namespace vibro::robustness
