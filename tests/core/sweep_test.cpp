// Parameter sweeps (core/analysis/sweep.h): section points against plain runs, the period a person
// reads off the diagram, continuation's hysteresis, any thread count giving the same output, and
// bad sweeps refused with the field named.
#include "core/analysis/sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/analysis/checked_run.h"
#include "core/model/parameter.h"
#include "tests/core/impact_oscillator.h"

namespace vibro {
namespace {

using testing::impact_oscillator;

SimOptions options(double rtol = 1e-10) {
  SimOptions o;
  o.rtol = rtol;
  o.atol = rtol * 1e-3;
  o.check = false;
  return o;
}

SweepSpec over_omega(double from, double to, int count, int transient = 100, int record = 32) {
  SweepSpec s;
  s.axis = {"model.pellets[0].Omega", from, to, count};
  s.transient = transient;
  s.record = record;
  return s;
}

SweepResult run(const Model& m, const SimOptions& o, const SweepSpec& s, int threads = 1) {
  EXPECT_FALSE(validate_sweep(m, s));
  SweepControl c;
  c.threads = threads;
  return run_sweep(m, o, s, c);
}

TEST(Sweep, EachSectionPointIsTheStateOfAPlainRunAtThatTime) {
  const SweepSpec spec = over_omega(4.0, 7.0, 3, 5, 4);
  const SweepResult r = run(impact_oscillator(5.0), options(1e-12), spec);
  ASSERT_EQ(r.runs.size(), 3u);
  for (const SweepRun& run : r.runs) {
    ASSERT_EQ(run.points.size(), 5u);  // k = 5 … 9
    const Model m = impact_oscillator(run.value);
    const double T = 2.0 * M_PI / run.value;
    for (std::size_t k = 0; k < run.points.size(); ++k) {
      const SectionPoint& p = run.points[k];
      EXPECT_NEAR(p.t, (5 + static_cast<double>(k)) * T, 1e-12 * p.t);
      SimOptions plain = options(1e-12);
      plain.t_end = p.t;
      const RunResult ref = simulate(m, plain);
      EXPECT_NEAR(p.phi, ref.summary.final[0].phi, 1e-9) << run.value << " k " << k;
      EXPECT_NEAR(p.dphi, ref.summary.final[0].dphi, 1e-8) << run.value << " k " << k;
    }
  }
}

// At Ω = 7 the oscillator settles on one impact per period (period 1); at Ω = 3.7 on a motion
// that repeats every second period, its two section points apart.
TEST(Sweep, ThePeriodOfTheMotionIsReadOffTheSection) {
  const SweepResult r = run(impact_oscillator(7.0), options(), over_omega(3.7, 7.0, 2));
  ASSERT_EQ(r.runs.size(), 2u);
  const SweepRun& doubled = r.runs[0];
  const SweepRun& single = r.runs[1];
  EXPECT_EQ(single.period, 1);
  EXPECT_DOUBLE_EQ(single.impacts_per_period, 1.0);
  EXPECT_EQ(doubled.period, 2);
  // Period 2 for real: consecutive points differ, every other one agrees.
  const auto& p = doubled.points;
  ASSERT_GE(p.size(), 3u);
  EXPECT_GT(std::abs(p[1].dphi - p[0].dphi), 1e-3);
  EXPECT_LT(std::abs(p[2].dphi - p[0].dphi), 1e-6);
  EXPECT_TRUE(single.trusted);
}

// Swept up in steps of 0.1, the oscillator keeps a motion of three impacts every two periods up
// to Ω = 5.7; swept down, one impact per period down to Ω = 5.5: two coexisting motions. Each
// persists when its last state is run on for a hundred periods more: attractors, not transients.
TEST(Sweep, ContinuationBothWaysShowsTheHysteresisLoop) {
  SweepSpec spec = over_omega(5.0, 6.0, 11);
  spec.continuation = Continuation::both;
  const SweepResult r = run(impact_oscillator(5.0), options(), spec);
  ASSERT_EQ(r.runs.size(), 22u);
  int differ = 0;
  for (int i = 0; i < 11; ++i) {
    const SweepRun& up = r.runs[i];
    const SweepRun& down = r.runs[11 + i];
    ASSERT_EQ(up.direction, +1);
    ASSERT_EQ(down.direction, -1);
    ASSERT_DOUBLE_EQ(up.value, down.value);
    if (up.value > 5.45 && up.value < 5.75) {
      EXPECT_DOUBLE_EQ(up.impacts_per_period, 1.5) << up.value;
      EXPECT_DOUBLE_EQ(down.impacts_per_period, 1.0) << down.value;
      ++differ;
    }
  }
  EXPECT_GE(differ, 3);
  // Both motions at Ω = 5.6, run on from the section's last points.
  for (int i : {6, 17}) {
    const SweepRun& run = r.runs[i];
    ASSERT_NEAR(run.value, 5.6, 1e-12);
    Model m = impact_oscillator(run.value);
    m.pellets[0].phi0 = run.points.back().phi;
    m.pellets[0].dphi0 = run.points.back().dphi;
    SimOptions o = options();
    o.t_end = 100 * 2.0 * M_PI / run.value;
    const RunResult on = simulate(m, o);
    const auto impacts = std::count_if(on.events.begin(), on.events.end(),
                                       [](const Event& e) { return e.kind == EventKind::limiter; });
    EXPECT_NEAR(static_cast<double>(impacts) / 100.0, run.impacts_per_period, 0.02) << i;
  }
}

TEST(Sweep, TheOutputIsTheSameForAnyNumberOfThreads) {
  SweepSpec spec = over_omega(3.0, 8.0, 12, 20, 8);
  spec.initial_states = 2;
  spec.axis2 = SweepAxis{"model.pellets[0].F0", 0.2, 0.4, 2};
  const Model m = impact_oscillator(5.0);
  const SweepResult one = run(m, options(1e-8), spec, 1);
  const SweepResult two = run(m, options(1e-8), spec, 2);
  const SweepResult three = run(m, options(1e-8), spec, 3);
  ASSERT_EQ(one.runs.size(), 48u);
  for (const SweepResult* other : {&two, &three}) {
    ASSERT_EQ(other->runs.size(), one.runs.size());
    for (std::size_t r = 0; r < one.runs.size(); ++r) {
      const SweepRun& a = one.runs[r];
      const SweepRun& b = other->runs[r];
      ASSERT_EQ(std::tie(a.value, a.value2, a.start, a.direction, a.period),
                std::tie(b.value, b.value2, b.start, b.direction, b.period));
      ASSERT_EQ(a.points.size(), b.points.size());
      for (std::size_t k = 0; k < a.points.size(); ++k) {
        ASSERT_EQ(a.points[k].phi, b.points[k].phi);
        ASSERT_EQ(a.points[k].dphi, b.points[k].dphi);
      }
    }
  }
}

TEST(Sweep, TheImpactSectionKeepsTheStateBeforeEveryLimiterImpact) {
  SweepSpec spec = over_omega(7.0, 7.0, 1, 50, 10);
  spec.section = SectionKind::impact;
  const SweepResult r = run(impact_oscillator(7.0), options(), spec);
  ASSERT_EQ(r.runs.size(), 1u);
  const SweepRun& run = r.runs[0];
  ASSERT_EQ(run.points.size(), 10u);  // one impact per period
  for (const SectionPoint& p : run.points) {
    EXPECT_EQ(p.limiter, 0);
    EXPECT_NEAR(std::remainder(p.phi, 2.0 * M_PI), 0.0, 1e-12);
    EXPECT_LT(p.dphi, 0.0);                           // arriving from above the stop, moving down
    EXPECT_NEAR(p.phase, run.points[0].phase, 1e-4);  // a period-1 motion strikes at one phase
  }
}

// A run's memory is its record's: the transient's events are not kept, so a transient longer
// than the event limit allows still runs, and the events kept are the full run's from t on.
TEST(Sweep, TheTransientsEventsAreNotKept) {
  const Model m = impact_oscillator(7.0);
  SimOptions full = options();
  full.t_end = 60 * 2.0 * M_PI / 7.0;
  SimOptions tail = full;
  tail.keep_events_from = 50 * 2.0 * M_PI / 7.0;
  const RunResult a = simulate(m, full);
  const RunResult b = simulate(m, tail);
  std::vector<double> kept;
  for (const Event& e : a.events)
    if (e.t >= tail.keep_events_from) kept.push_back(e.t);
  ASSERT_EQ(b.events.size(), kept.size());
  ASSERT_GT(a.events.size(), 2 * b.events.size());
  for (std::size_t k = 0; k < kept.size(); ++k) EXPECT_EQ(b.events[k].t, kept[k]);

  SimOptions tight = options();
  tight.max_events = static_cast<long>(b.events.size()) + 2;  // the record's, not the transient's
  SweepSpec spec = over_omega(7.0, 7.0, 1, 50, 10);
  spec.section = SectionKind::impact;
  const SweepResult r = run(m, tight, spec);
  ASSERT_EQ(r.runs.size(), 1u);
  EXPECT_EQ(r.runs[0].termination, Termination::completed) << r.runs[0].message;
  EXPECT_EQ(r.runs[0].points.size(), 10u);
}

TEST(Sweep, BadSweepsAreRefusedNamingTheField) {
  const Model m = impact_oscillator(5.0);
  auto field = [&](const SweepSpec& s) {
    const auto e = validate_sweep(m, s);
    return e ? e->field : std::string("accepted");
  };
  SweepSpec s = over_omega(3.0, 8.0, 10);
  EXPECT_EQ(field(s), "accepted");
  s.axis.parameter = "model.pellets[3].F0";
  EXPECT_EQ(field(s), "sweep.parameter");
  s.axis.parameter = "model.pellets[0].colour";
  EXPECT_EQ(field(s), "sweep.parameter");
  s = over_omega(3.0, 8.0, 0);
  EXPECT_EQ(field(s), "sweep.count");
  s = over_omega(3.0, 8.0, 10);
  s.axis2 = SweepAxis{"model.pellets[0].F0", 0.5, 0.2, 5};
  EXPECT_EQ(field(s), "sweep.parameter2.to");
  s = over_omega(3.0, 8.0, 10);
  s.record = 0;
  EXPECT_EQ(field(s), "sweep.record");
  // A value that makes the model invalid names the model's field.
  SweepSpec r{};
  r.axis = {"model.R", -1.0, 1.0, 3};
  EXPECT_EQ(field(r), "model.R");
  // No forcing: only the impact section.
  Model free = m;
  free.pellets[0].force = {};
  SweepSpec k{};
  k.axis = {"model.limiters[0].k", 0.5, 0.9, 3};
  EXPECT_EQ(validate_sweep(free, k)->field, "sweep.section");
  k.section = SectionKind::impact;
  EXPECT_FALSE(validate_sweep(free, k));
}

// Each value of a sweep must make a model a scene of its own could hold, not only its ends: two
// pellets swept through each other, limiters swept onto each other, and a pair of a 2-D sweep
// inside the grid are refused, naming the swept field and the value.
TEST(Sweep, EveryValueIsCheckedAsASceneOfItsOwn) {
  Model two = impact_oscillator(5.0);
  two.pellets.push_back(two.pellets[0]);
  two.pellets[0].phi0 = 0.1;
  two.pellets[1].phi0 = 0.5;
  SweepSpec s = over_omega(3.0, 8.0, 3);
  s.axis = {"model.pellets[1].phi0", 0.0, 0.2, 3};  // 0, 0.1, 0.2: the middle run coincides
  auto e = validate_sweep(two, s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->field, "model.pellets[1].phi0");
  EXPECT_NE(e->message.find("model.pellets[1].phi0 = 0.1"), std::string::npos) << e->message;
  s.axis.count = 2;  // 0 and 0.2 only
  EXPECT_FALSE(validate_sweep(two, s));

  // Limiters at 0 and 1 rad; the first swept over 0.5 … 1.5 meets the second at 1.
  Model stops = impact_oscillator(5.0);
  stops.limiters.push_back({1.0, 0.8, false, -1, {}});
  s.axis = {"model.limiters[0].angle", 0.5, 1.5, 3};
  e = validate_sweep(stops, s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->field, "model.limiters[0].angle");  // the swept one, not the one it meets
  EXPECT_NE(e->message.find("model.limiters[1].angle coincides"), std::string::npos) << e->message;
  EXPECT_NE(e->message.find("= 1,"), std::string::npos) << e->message;

  // A 2-D sweep whose four corners are good, and one pair inside where the pellets coincide.
  s.axis = {"model.pellets[1].phi0", 0.0, 0.2, 2};
  s.axis2 = SweepAxis{"model.pellets[0].phi0", 0.1, 0.3, 3};
  e = validate_sweep(two, s);
  ASSERT_TRUE(e);
  EXPECT_NE(e->message.find("model.pellets[1].phi0 = 0.2, model.pellets[0].phi0 = 0.2"),
            std::string::npos)
      << e->message;
}

// The points a sweep may keep: an impact section of a pellet rattling between two elastic stops
// stops at the bound, keeps no more than it, and names the field.
TEST(Sweep, ABoundOnThePointsStopsTheSweepNamingTheField) {
  Model m = impact_oscillator(5.0);
  m.pellets[0].force = {};
  m.pellets[0].phi0 = 0.0;
  m.pellets[0].dphi0 = 1.5;
  m.limiters = {{-0.05, 1.0, false, -1, {}}, {0.05, 1.0, false, -1, {}}};
  SweepSpec spec;
  spec.axis = {"model.pellets[0].dphi0", 1.0, 2.0, 6};
  spec.transient = 0;
  spec.record = 4;
  spec.section = SectionKind::impact;
  ASSERT_FALSE(validate_sweep(m, spec));
  SweepControl all;
  const SweepResult whole = run_sweep(m, options(1e-8), spec, all);
  ASSERT_EQ(whole.runs.size(), 6u);
  EXPECT_FALSE(whole.stopped);
  const long each = static_cast<long>(whole.runs[0].points.size());
  ASSERT_GT(each, 20);
  for (int threads : {1, 2}) {
    SweepControl bounded;
    bounded.threads = threads;
    bounded.max_points = 2 * each + each / 2;
    const SweepResult r = run_sweep(m, options(1e-8), spec, bounded);
    ASSERT_TRUE(r.stopped);
    EXPECT_EQ(r.stopped->field, "sweep.record");
    EXPECT_NE(r.stopped->message.find(std::to_string(bounded.max_points)), std::string::npos);
    EXPECT_LT(r.runs.size(), 6u);
    long kept = 0;
    for (const SweepRun& run : r.runs) kept += static_cast<long>(run.points.size());
    EXPECT_LE(kept, bounded.max_points);
  }
}

// A sweep's wall-clock budget: once spent, no run starts, and the result says so.
TEST(Sweep, AWallClockBudgetStopsTheSweep) {
  SweepControl c;
  c.budget_ms = 0.0;
  const SweepResult r =
      run_sweep(impact_oscillator(5.0), options(1e-8), over_omega(3.0, 8.0, 5, 5, 5), c);
  ASSERT_TRUE(r.stopped);
  EXPECT_EQ(r.stopped->field, "sweep.count");
  EXPECT_NE(r.stopped->message.find("wall-clock budget"), std::string::npos);
  EXPECT_LE(r.runs.size(), 1u);
  EXPECT_FALSE(r.cancelled);
}

TEST(Parameter, PathsNameTheModelsNumericFields) {
  Model m = impact_oscillator(5.0);
  EXPECT_FALSE(set_parameter(m, "model.pellets[0].F0", 0.7));
  EXPECT_EQ(m.pellets[0].force.F0, 0.7);
  EXPECT_FALSE(set_parameter(m, "model.limiters[0].k", 0.5));
  EXPECT_EQ(m.limiters[0].k, 0.5);
  EXPECT_EQ(get_parameter(m, "model.R"), 0.5);
  EXPECT_TRUE(set_parameter(m, "model.pellets[1].F0", 1.0));
  EXPECT_TRUE(set_parameter(m, "model.pellets[0]F0", 1.0));
  EXPECT_TRUE(set_parameter(m, "pellets[0].F0", 1.0));
  EXPECT_FALSE(get_parameter(m, "model.limiters[2].angle"));
}

}  // namespace
}  // namespace vibro

namespace vibro {
namespace {

// A sweep holds each run to the run's limit of simulated time and the whole to its budget of
// periods, as a scene's run is held: the spec checks itself, whoever reads it.
TEST(Sweep, ItsSimulatedTimeIsHeldToTheLimits) {
  const Model m = impact_oscillator(5.0);
  const SweepSpec s = over_omega(3.0, 8.0, 10);  // 132 periods of at most 2π/3 s a run
  Limits limits;
  EXPECT_FALSE(validate_sweep(m, s, limits));
  limits.t_end = 200.0;  // the run at Ω = 3 lasts 276 s
  EXPECT_EQ(validate_sweep(m, s, limits)->field, "sweep.record");
  limits = {};
  limits.sweep_periods = 1000.0;  // 10 runs × 132 periods
  EXPECT_EQ(validate_sweep(m, s, limits)->field, "sweep.count");
}

}  // namespace
}  // namespace vibro
