// Run results as JSON: the API's shape, and no NaN ever in the output.
#include "io/result_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace vibro {
namespace {

TEST(ResultJson, HasTheApiShapeAndNoNonFiniteNumbers) {
  Model m;
  m.pellets.resize(1);
  m.limiters = {{0.5, 0.5, false, -1, {}}};
  RunResult run;
  Event e;
  e.t = 0.1;
  e.kind = EventKind::limiter;
  e.pellets = {0};
  e.limiter = 0;
  e.phi = 0.5;
  e.dphi_before = {2.0};
  e.dphi_after = {std::numeric_limits<double>::quiet_NaN()};
  run.events.push_back(e);
  run.summary.final = {
      {0.5, std::numeric_limits<double>::infinity(), PelletState::resting_at_limiter, 0}};
  run.summary.last_impact = {1, 0.1};
  run.summary.limiter_impacts = 1;
  run.summary.impacts_by_limiter = {{1}};
  run.stats.method = "auto";
  run.stats.error_estimate = std::numeric_limits<double>::quiet_NaN();
  const nlohmann::json j = result_to_json(run, m);
  EXPECT_EQ(j["events"][0]["kind"], "limiter");
  EXPECT_EQ(j["events"][0]["limiter"], 0);
  EXPECT_TRUE(j["events"][0]["dphi_after"][0].is_null());
  EXPECT_TRUE(j["summary"]["final"][0]["dphi"].is_null());
  EXPECT_EQ(j["summary"]["final"][0]["state"], "resting_at_limiter");
  EXPECT_EQ(j["summary"]["last_impact"]["index"], 1);
  EXPECT_TRUE(j["stats"]["error_estimate"].is_null());
  for (const char* key : {"method", "steps", "rejected", "rhs_evals", "wall_ms", "error_estimate"})
    EXPECT_TRUE(j["stats"].contains(key)) << key;
  EXPECT_EQ(j.dump().find("NaN"), std::string::npos);
  EXPECT_FALSE(j.contains("trajectories"));
}

TEST(ResultJson, TheAnswerCountsInTheSingularWhenThereIsOne) {
  // "1 impacts", "1 limiter impacts" and "1 collisions" were printed.
  Model m;
  m.pellets.resize(1);
  RunResult run;
  run.summary.final = {{0.5, 1.0, PelletState::sliding, -1}};
  run.summary.last_impact = {1, 0.1};
  run.summary.limiter_impacts = 1;
  run.summary.collisions = 1;
  run.summary.ends_vibro_impact = false;
  run.stats.t_reached = 2.0;
  const std::string answer = result_to_json(run, m)["summary"]["answer"];
  EXPECT_NE(answer.find("1 impact (1 limiter impact, 1 collision)"), std::string::npos) << answer;
  run.summary.last_impact = {2, 0.2};
  run.summary.collisions = 0;
  const std::string two = result_to_json(run, m)["summary"]["answer"];
  EXPECT_NE(two.find("2 impacts (1 limiter impact, 0 collisions)"), std::string::npos) << two;
}

}  // namespace
}  // namespace vibro
