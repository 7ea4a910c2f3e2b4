// The driver and its observers (core/run/simulate.h, core/run/observer.h): what the hooks see,
// that outputs are opt-in and leave the run as it is, and each standard output on its own.
#include "core/run/observers.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/analysis/checked_run.h"
#include "core/run/simulate.h"
#include "io/presets.h"
#include "tests/core/scenes.h"

namespace vibro {
namespace {

// Counts the hooks and checks their order in time.
class HookLog : public RunObserver {
 public:
  void on_start(const Vec& y0) override {
    ++starts;
    size = y0.size();
  }
  void on_instant(const InstantView& in) override {
    EXPECT_GE(in.t, last_t);
    EXPECT_EQ(in.y_after.size(), size);
    EXPECT_EQ(in.unsnapped == nullptr, instants == 0);  // only the start is not snapped
    last_t = in.t;
    ++instants;
    events += static_cast<long>(in.events.size());
  }
  void on_interval(double t, const Vec&, const MotionInterval&) override {
    EXPECT_GE(t, last_t);
    ++intervals;
  }
  void on_step(const StepSamples& s) override {
    EXPECT_LT(s.a, s.b);
    EXPECT_EQ(s.times.back(), s.b);
    ++steps;
  }
  void on_step_end(double t, const Vec&, const MotionInterval&, bool at_event) override {
    EXPECT_GE(t, last_t);
    last_t = t;
    step_events += at_event;
  }
  void on_end(const EndView& end, RunResult& result) override {
    ++ends;
    EXPECT_EQ(end.t_reached, result.stats.t_reached);
  }

  int starts = 0, ends = 0;
  long instants = 0, intervals = 0, steps = 0, step_events = 0, events = 0;
  Eigen::Index size = 0;
  double last_t = 0.0;
};

Scene unchecked(const char* preset) {
  Scene scene = testing::preset(preset);
  scene.sim.check = false;
  return scene;
}

TEST(Observers, TheHooksFollowTheRun) {
  const Scene scene = unchecked("paper");
  const auto stepper = make_stepper(scene.model, scene.sim);
  HookLog log;
  RunObserver* observers[] = {&log};
  const RunResult run = simulate(scene.model, scene.sim, *stepper, observers);
  EXPECT_EQ(log.starts, 1);
  EXPECT_EQ(log.ends, 1);
  EXPECT_EQ(log.steps, run.stats.steps);         // every accepted step
  EXPECT_EQ(log.instants, log.step_events + 1);  // each event step, and the start
  EXPECT_EQ(log.intervals, log.instants);
  EXPECT_EQ(run.stats.termination, Termination::completed);
  EXPECT_EQ(run.stats.t_reached, scene.sim.t_end);
  EXPECT_GT(log.events, 0);
}

TEST(Observers, OutputsAreOptInAndLeaveTheRunAsItIs) {
  const Scene scene = unchecked("impact-oscillator");
  const RunResult bare = simulate(scene.model, scene.sim, *make_stepper(scene.model, scene.sim),
                                  std::span<RunObserver* const>{});
  const RunResult full = simulate(scene.model, scene.sim);
  EXPECT_TRUE(bare.events.empty());  // no event log attached
  EXPECT_TRUE(bare.tracks.empty());
  EXPECT_FALSE(full.events.empty());
  EXPECT_EQ(bare.stats.steps, full.stats.steps);
  EXPECT_EQ(bare.stats.rejected, full.stats.rejected);
  EXPECT_EQ(bare.stats.t_reached, full.stats.t_reached);
}

TEST(Observers, StepsLandOnSectionStops) {
  Scene scene = unchecked("impact-oscillator");
  const double period = scene.sim.t_end / 7.0;
  std::vector<double> times;
  for (int k = 1; k <= 6; ++k) times.push_back(k * period);
  SectionStops stops(scene.model, times);
  EventLog events(scene.model, scene.sim.t_end, scene.sim.keep_events_from);
  RunObserver* observers[] = {&events, &stops};
  const RunResult run =
      simulate(scene.model, scene.sim, *make_stepper(scene.model, scene.sim), observers);
  ASSERT_EQ(run.stops.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    EXPECT_EQ(run.stops[k].t, times[k]);
    ASSERT_EQ(run.stops[k].pellets.size(), scene.model.pellets.size());
    EXPECT_TRUE(std::isfinite(run.stops[k].pellets[0].phi));
  }
  // The same stops through the convenience entry hold the same states.
  scene.sim.stops = times;
  const RunResult same = simulate(scene.model, scene.sim);
  ASSERT_EQ(same.stops.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k)
    EXPECT_EQ(same.stops[k].pellets[0].phi, run.stops[k].pellets[0].phi);
}

TEST(Observers, TheEventLogKeepsEventsFromItsStartAndTheBudgetCountsThoseAlone) {
  Scene scene = unchecked("impact-oscillator");
  const RunResult all = simulate(scene.model, scene.sim);
  ASSERT_GT(all.events.size(), 4u);
  const double from = all.events[all.events.size() / 2].t;
  scene.sim.keep_events_from = from;
  const RunResult late = simulate(scene.model, scene.sim);
  ASSERT_FALSE(late.events.empty());
  EXPECT_GE(late.events.front().t, from);
  EXPECT_EQ(late.events.back().t, all.events.back().t);
  // A budget of the kept events alone lets the run reach its end.
  scene.sim.max_events = static_cast<long>(late.events.size()) + 1;
  EXPECT_EQ(simulate(scene.model, scene.sim).stats.termination, Termination::completed);
}

TEST(Observers, TheSummarysCountsAddUp) {
  // Each impact counts once, in its kind's total: the limiter impacts, collisions and chatter
  // sequences add up to the index of the last impact, and the limiter impacts per limiter and
  // pellet to the limiter impacts. mass-ratio's last impact, a cascade of two pellets taken to
  // its plastic limit against a limiter (a collision event naming the limiter), was counted as
  // a collision and a limiter impact: "impact 376 (188 limiter impacts, 189 collisions)", with
  // impacts_by_limiter summing to 187.
  for (const PresetText& p : presets()) {
    const Scene scene = testing::preset(std::string(p.name));
    SimOptions o = scene.sim;
    o.check = false;
    const RunResult r = simulate(scene.model, o);
    const Summary& s = r.summary;
    EXPECT_EQ(s.limiter_impacts + s.collisions + s.chatter_sequences, s.last_impact.index)
        << p.name;
    int by_limiter = 0;
    for (const auto& row : s.impacts_by_limiter)
      for (int n : row) by_limiter += n;
    EXPECT_EQ(by_limiter, s.limiter_impacts) << p.name;
  }
}

TEST(Observers, ThePathHoldsEveryInstantUpToItsLimit) {
  Scene scene = unchecked("impact-oscillator");
  PathKeeper path(scene.sim.t_end, scene.sim.keep_events_from, 5);
  RunObserver* observers[] = {&path};
  const RunResult run =
      simulate(scene.model, scene.sim, *make_stepper(scene.model, scene.sim), observers);
  ASSERT_EQ(run.path.size(), 5u);
  EXPECT_EQ(run.path.front().t, 0.0);
  for (std::size_t k = 1; k < run.path.size(); ++k) {
    EXPECT_EQ(run.path[k - 1].t_end, run.path[k].t);  // each segment ends where the next starts
    EXPECT_FALSE(run.path[k].events.empty());
    EXPECT_EQ(run.path[k].normal_sides.size(), run.path[k].bodies.size());
  }
}

TEST(Observers, TheEnergyCheckReportsTheRunsConsistency) {
  const Scene scene = unchecked("paper");
  EnergyCheck energy(scene.model);
  RunObserver* observers[] = {&energy};
  const RunResult run =
      simulate(scene.model, scene.sim, *make_stepper(scene.model, scene.sim), observers);
  EXPECT_GT(run.stats.energy_defect, 0.0);
  EXPECT_LT(run.stats.energy_defect, 1e-5);
  EXPECT_EQ(run.stats.error_estimate,
            std::max(run.stats.energy_defect, run.stats.first_integral_residual));
  EXPECT_EQ(run.stats.energy_defect, simulate(scene.model, scene.sim).stats.energy_defect);
}

// The driver makes the per-step calls to the observers that override them alone: what each
// standard observer takes is read from its declarations, and one that does not say takes all.
TEST(Observers, PerStepCallsGoWhereTheyAreOverridden) {
  const auto takes = [](RunObserver::PerStep p) {
    return std::array<bool, 4>{p.landing, p.step, p.step_end, p.settled};
  };
  using A = std::array<bool, 4>;
  EXPECT_EQ(takes(per_step_of<Recording>()), (A{false, true, true, false}));
  EXPECT_EQ(takes(per_step_of<SectionStops>()), (A{true, false, false, true}));
  EXPECT_EQ(takes(per_step_of<PathKeeper>()), (A{false, false, false, false}));
  EXPECT_EQ(takes(per_step_of<EventLog>()), (A{false, false, false, false}));
  EXPECT_EQ(takes(per_step_of<EnergyCheck>()), (A{false, false, true, false}));
  EXPECT_EQ(takes(HookLog().per_step()), (A{true, true, true, true}));
}

}  // namespace
}  // namespace vibro
