// Work-precision: the true error falls as the tolerance shrinks, for every method, against
// each kind of reference.
#include "core/analysis/work_precision.h"

#include <gtest/gtest.h>

#include <map>

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
    // Taylor's order grows as the tolerance shrinks (16 at 1e-10 against 9 at 1e-4), so its
    // steps barely grow and may be fewer; `auto` runs DOPRI5 at 1e-4 and Taylor at 1e-10
    // (kAutoTaylorRtol; frictionless-elastic: 78 steps against 72).
    if (method != Method::taylor && method != Method::automatic) {
      EXPECT_GT(points[2]->steps, points[0]->steps) << method_name(method);
    }
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

namespace vibro {
namespace {

// The whole measurement answers to its deadline: forced at 1e9 rad/s, each run needs far more
// than its share, and 42 runs of a share each held a server worker for 5 s. The points not
// reached are left out and said.
TEST(WorkPrecision, TheWholeMeasurementAnswersToItsDeadline) {
  Scene s = testing::preset("paper");
  s.model.pellets[0].force.Omega = 1e9;
  SimOptions o = s.sim;
  o.deadline_ms = 20.0;
  WorkPrecisionOptions w;
  w.repeats = 1;
  w.deadline_ms = 60.0;
  const WorkPrecisionReport r = work_precision(s.model, o, w);
  EXPECT_LT(r.points.size(), w.methods.size() * w.rtols.size());
  EXPECT_NE(r.message.find("deadline of 60 ms"), std::string::npos) << r.message;
  for (const WorkPrecisionPoint& p : r.points) EXPECT_FALSE(p.completed);
}

}  // namespace
}  // namespace vibro
