// Event times converge as the tolerance shrinks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/analysis/checked_run.h"
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

// An angle is held to its tolerance by its place on the circle, not by the turns that brought it
// there: a frictionless swing of 0.01 rad about the bottom, 30 turns on (φ ≈ 188.5 rad), turns
// when the same swing before any turn does. Held relative to the unwrapped angle, DOP853 at rtol
// 1e-10 put the turned swing's reversals 9.5e-9 s off, the plain one's 7.4e-11 s.
TEST(Convergence, AnAngleIsHeldByItsPlaceNotItsTurns) {
  const Model plain = testing::one_pellet(0.0, 0.01, 0.0);
  Model turned = plain;
  turned.pellets[0].phi0 += 60.0 * std::numbers::pi;
  SimOptions o = testing::recorded(plain, 5.0, Method::dop853, 1e-13, 1e-16);
  o.record.clear();
  const std::vector<Event> reference = simulate(plain, o).events;
  ASSERT_EQ(reference.size(), 7u);
  for (Method method : {Method::dopri5, Method::dop853, Method::radau5}) {
    o.method = method;
    o.rtol = 1e-10;
    o.atol = 1e-12;
    double error[2] = {0.0, 0.0};
    for (int k : {0, 1}) {
      const std::vector<Event> events = simulate(k ? turned : plain, o).events;
      ASSERT_EQ(events.size(), reference.size()) << testing::method_at(method, o.rtol);
      for (std::size_t j = 0; j < events.size(); ++j)
        error[k] = std::max(error[k], std::abs(events[j].t - reference[j].t));
    }
    EXPECT_LT(error[1], 3.0 * std::max(error[0], 1e-12)) << testing::method_at(method, o.rtol);
  }
}

}  // namespace
}  // namespace vibro
