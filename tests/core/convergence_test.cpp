// Event times converge as the tolerance shrinks.
#include <gtest/gtest.h>

#include <cmath>

#include "core/simulate.h"
#include "scenes.h"

namespace vibro {
namespace {

std::vector<double> impact_times(const RunResult& run, std::size_t count) {
  std::vector<double> t;
  for (const Event& e : run.events) {
    if (e.kind == EventKind::limiter || e.kind == EventKind::collision) t.push_back(e.t);
    if (t.size() == count) break;
  }
  return t;
}

TEST(Convergence, PaperSceneImpactTimesConvergeAsToleranceShrinks) {
  const Scene scene = testing::preset("paper");
  SimOptions o = scene.sim;
  o.t_end = 1.5;
  o.method = Method::dop853;
  o.rtol = 1e-13;
  o.atol = 1e-14;
  const std::vector<double> reference = impact_times(simulate(scene.model, o), 4);
  ASSERT_EQ(reference.size(), 4u);
  for (Method method : {Method::dopri5, Method::dop853, Method::radau5}) {
    double previous = 1.0;
    for (double rtol : {1e-5, 1e-7, 1e-9, 1e-11}) {
      o.method = method;
      o.rtol = rtol;
      o.atol = rtol * 1e-2;
      const std::vector<double> t = impact_times(simulate(scene.model, o), 4);
      ASSERT_EQ(t.size(), 4u);
      double err = 0.0;
      for (std::size_t k = 0; k < t.size(); ++k) err = std::max(err, std::abs(t[k] - reference[k]));
      EXPECT_LE(err, std::max(previous, 1e-12)) << method_name(method) << " rtol " << rtol;
      previous = err;
    }
    EXPECT_LT(previous, 1e-8) << method_name(method);
  }
}

}  // namespace
}  // namespace vibro
