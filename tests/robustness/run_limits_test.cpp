// Every run ends: the wall-clock deadline, the event limit and the step limit each stop a run
// that would go on far longer, promptly and with a message that names the time and the limit.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
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

// Runs the scene with its options changed by `limit`, and checks how and why it stopped.
RunResult expect_stopped(const char* text, const std::function<void(SimOptions&)>& limit,
                         Termination termination, const std::string& why) {
  const Scene scene = parsed(text);
  SimOptions options = scene.sim;
  options.deadline_ms = 10000.0;  // no test may hang
  limit(options);
  const RunResult run = run_checked(scene, options);
  EXPECT_EQ(run.stats.termination, termination);
  EXPECT_NE(run.stats.message.find(why), std::string::npos) << run.stats.message;
  return run;
}

TEST(RunLimits, DeadlineStopsALongRunPromptly) {
  const auto start = std::chrono::steady_clock::now();
  const RunResult run = expect_stopped(
      kLongForcedRun, [](SimOptions& o) { o.deadline_ms = 100.0; }, Termination::deadline,
      "deadline of 100 ms");
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  EXPECT_LT(run.stats.t_reached, 1e6);
  EXPECT_LT(wall.count(),
            5.0);  // generous: sanitizer builds on a busy machine, not a timing target
}

TEST(RunLimits, EventLimitStopsARattleCleanly) {
  const RunResult run = expect_stopped(
      kRattle, [](SimOptions& o) { o.max_events = 500; }, Termination::event_limit,
      "its limit of 500 events");
  EXPECT_LE(run.events.size(), 500u);
  EXPECT_GT(run.stats.t_reached, 0.5);  // about 1 s of rattling at 2 ms per impact
  EXPECT_LT(run.stats.t_reached, 2.0);
}

TEST(RunLimits, StepLimitStopsALongRunCleanly) {
  const RunResult run = expect_stopped(
      kLongForcedRun, [](SimOptions& o) { o.max_steps = 1000; }, Termination::step_limit,
      "its limit of 1000 steps");
  EXPECT_LE(run.stats.steps, 1000);
}

}  // namespace
}  // namespace vibro::robustness
