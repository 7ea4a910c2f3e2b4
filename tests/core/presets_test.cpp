// Every preset finishes under every method, without NaN, and the paper scene answers the
// paper's question as MODEL.md describes it.
#include "io/presets.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/analysis/checked_run.h"
#include "scenes.h"

namespace vibro {
namespace {

class EveryPreset : public ::testing::TestWithParam<Method> {};

TEST_P(EveryPreset, FinishesWithoutNaN) {
  for (const PresetText& p : presets()) {
    const Scene scene = testing::preset(std::string(p.name));
    SimOptions o = scene.sim;
    o.method = GetParam();
    o.record.assign(scene.model.size(), true);
    const RunResult run = simulate(scene.model, o);
    EXPECT_EQ(run.stats.termination, Termination::completed) << p.name << ": " << run.stats.message;
    EXPECT_TRUE(testing::all_finite(run)) << p.name;
    EXPECT_DOUBLE_EQ(run.stats.t_reached, scene.sim.t_end) << p.name;
    // No event is reported twice: the same kind on the same pellets at the same instant.
    for (std::size_t k = 1; k < run.events.size(); ++k) {
      const Event& a = run.events[k - 1];
      const Event& b = run.events[k];
      EXPECT_FALSE(a.t == b.t && a.kind == b.kind && a.pellets == b.pellets &&
                   a.limiter == b.limiter && a.kind != EventKind::collision)
          << p.name << " doubled " << event_kind_name(a.kind) << " at t = " << a.t;
    }
  }
}

TEST_P(EveryPreset, CalmStepsFindTheSameEvents) {
  // Searching a calm step at its end alone (core/events/watch.h) finds the events that searching
  // inside every step finds, at the same times to well below the tolerance.
  for (const PresetText& p : presets()) {
    const Scene scene = testing::preset(std::string(p.name));
    SimOptions o = scene.sim;
    o.method = GetParam();
    o.check = false;
    const RunResult cut = simulate(scene.model, o);
    o.sample_every_step = true;
    const RunResult every = simulate(scene.model, o);
    ASSERT_EQ(cut.events.size(), every.events.size()) << p.name;
    for (std::size_t k = 0; k < cut.events.size(); ++k) {
      EXPECT_EQ(cut.events[k].kind, every.events[k].kind) << p.name << ", event " << k;
      EXPECT_NEAR(cut.events[k].t, every.events[k].t, 1e-3 * o.rtol * (1.0 + every.events[k].t))
          << p.name << ", event " << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, EveryPreset,
                         ::testing::Values(Method::dopri5, Method::dop853, Method::radau5,
                                           Method::automatic, Method::taylor),
                         [](const auto& info) { return std::string(method_name(info.param)); });

TEST(PaperScene, AnswersThePapersQuestion) {
  const Scene scene = testing::preset("paper");
  const RunResult run = simulate(scene.model, scene.sim);
  ASSERT_EQ(run.stats.termination, Termination::completed) << run.stats.message;
  // MODEL.md: pellet 1 goes over the top, chatters into the left limiter and rests at
  // 2π − delta_2 = 3π/2; pellet 2 comes to rest in its friction zone near 0.
  const FinalState& p1 = run.summary.final[0];
  const FinalState& p2 = run.summary.final[1];
  EXPECT_EQ(p1.state, PelletState::resting_at_limiter);
  EXPECT_EQ(p1.limiter, 1);
  EXPECT_NEAR(p1.phi, 3 * M_PI / 2, 1e-12);
  EXPECT_EQ(p2.state, PelletState::stuck);
  EXPECT_LE(std::abs(wrap_angle(p2.phi)), scene.model.alpha0);
  EXPECT_GE(run.summary.collisions, 5);
  EXPECT_GT(run.summary.last_impact.index, 10);
  EXPECT_FALSE(testing::events_of(run, EventKind::chatter).empty());
}

// Pellet 1 of the paper scene approaches its rest at limiter 2 through chatter, the normal force
// negative in twelve stretches ever closer together: one warning for the approach (it was
// twelve), and its own for the stretch near t = 0.8 s, long before.
TEST(PaperScene, OneWarningForOneApproachOfNegativeNormalForce) {
  const Scene scene = testing::preset("paper");
  SimOptions o = scene.sim;
  o.check = false;
  const RunResult run = simulate(scene.model, o);
  ASSERT_EQ(run.warnings.size(), 2u);
  EXPECT_LT(run.warnings[0].t_end, 1.0);
  const Warning& approach = run.warnings[1];
  EXPECT_EQ(approach.code, "negative_normal_force");
  EXPECT_LT(approach.t_begin, 6.0);
  EXPECT_GT(approach.t_end, 7.259);
  EXPECT_NE(approach.message.find("in 12 stretches"), std::string::npos) << approach.message;
}

}  // namespace
}  // namespace vibro
