// Every run ends: the wall-clock deadline, the event limit and the step limit each stop a run
// that would go on far longer, promptly and with a message that names the time and the limit.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "tests/robustness/scene_runs.h"

namespace vibro::robustness {
namespace {

// A forced pellet between two limiters, for a million seconds: hours of work unbounded.
constexpr const char* kLongForcedRun = R"({"model": {"R": 0.5, "alpha0": 0.05, "pellets": [
    {"m": 0.2, "phi0": 0, "dphi0": 10, "F0": 1.2, "Omega": 3.3}],
    "limiters": [{"angle": 0.7, "k": 0.5}, {"angle": -1.5, "k": 0.5}]}, "t_end": 1e6})";

// Elastic limiters 0.02 rad apart and no friction: an impact every 2 ms, for ever.
constexpr const char* kRattle = R"({"model": {"R": 0.5, "pellets": [
    {"m": 0.2, "phi0": 0, "dphi0": 10}],
    "limiters": [{"angle": 0.01, "k": 1}, {"angle": -0.01, "k": 1}]}, "t_end": 1000})";

TEST(RunLimits, DeadlineStopsALongRunPromptly) {
  const Scene scene = parsed(kLongForcedRun);
  SimOptions options = scene.sim;
  options.deadline_ms = 100.0;
  const auto start = std::chrono::steady_clock::now();
  const RunResult run = run_checked(scene, options);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(run.stats.termination, Termination::deadline);
  EXPECT_NE(run.stats.message.find("deadline of 100 ms"), std::string::npos) << run.stats.message;
  EXPECT_LT(run.stats.t_reached, 1e6);
  EXPECT_LT(wall_s, 5.0);  // generous: sanitizer builds on a busy machine, not a timing target
}

TEST(RunLimits, EventLimitStopsARattleCleanly) {
  const Scene scene = parsed(kRattle);
  SimOptions options = scene.sim;
  options.max_events = 500;
  options.deadline_ms = 10000.0;
  const RunResult run = run_checked(scene, options);
  EXPECT_EQ(run.stats.termination, Termination::event_limit);
  EXPECT_NE(run.stats.message.find("the event limit"), std::string::npos) << run.stats.message;
  EXPECT_LE(run.events.size(), 500u);
  EXPECT_GT(run.stats.t_reached, 0.5);  // about 1 s of rattling at 2 ms per impact
  EXPECT_LT(run.stats.t_reached, 2.0);
}

TEST(RunLimits, StepLimitStopsALongRunCleanly) {
  const Scene scene = parsed(kLongForcedRun);
  SimOptions options = scene.sim;
  options.max_steps = 1000;
  options.deadline_ms = 10000.0;
  const RunResult run = run_checked(scene, options);
  EXPECT_EQ(run.stats.termination, Termination::step_limit);
  EXPECT_NE(run.stats.message.find("the step limit"), std::string::npos) << run.stats.message;
  EXPECT_LE(run.stats.steps, 1000 + 1);
}

}  // namespace
}  // namespace vibro::robustness
