// Work-precision: the true error falls as the tolerance shrinks, for every method, against
// each kind of reference.
#include <gtest/gtest.h>

#include <map>

#include "core/work_precision.h"
#include "scenes.h"

namespace vibro {
namespace {

void expect_error_falls(const Model& model, const SimOptions& base, ErrorReference expected) {
  WorkPrecisionOptions o;
  o.rtols = {1e-4, 1e-7, 1e-10};
  o.repeats = 1;
  const WorkPrecisionReport r = work_precision(model, base, o);
  EXPECT_EQ(r.reference, expected);
  ASSERT_EQ(r.points.size(), o.methods.size() * o.rtols.size());
  std::map<Method, std::vector<const WorkPrecisionPoint*>> by_method;
  for (const WorkPrecisionPoint& p : r.points) {
    EXPECT_TRUE(p.completed);
    EXPECT_GT(p.median_ms, 0.0);
    by_method[p.method].push_back(&p);
  }
  for (const auto& [method, points] : by_method) {
    ASSERT_EQ(points.size(), 3u);
    EXPECT_LT(points[2]->error, points[0]->error / 100.0) << method_name(method);
    EXPECT_LT(points[2]->error, 1e-6) << method_name(method);
    EXPECT_GT(points[2]->steps, points[0]->steps) << method_name(method);
  }
}

TEST(WorkPrecision, PaperSceneAgainstAReferenceRun) {
  const Scene s = testing::preset("paper");
  SimOptions o = s.sim;
  o.t_end = 4.0;
  expect_error_falls(s.model, o, ErrorReference::reference_run);
}

TEST(WorkPrecision, UnforcedFrictionAgainstTheFirstIntegral) {
  Model m = testing::one_pellet(0.05, 0.0, 9.0);
  m.limiters = {{0.9, 0.7, false, -1, {}}, {-0.8, 0.6, false, -1, {}}};
  SimOptions o;
  o.t_end = 3.0;
  expect_error_falls(m, o, ErrorReference::first_integral);
}

TEST(WorkPrecision, FrictionlessAgainstTheEnergy) {
  const Scene s = testing::preset("frictionless-elastic");
  SimOptions o = s.sim;
  o.t_end = 5.0;
  expect_error_falls(s.model, o, ErrorReference::energy);
}

}  // namespace
}  // namespace vibro
