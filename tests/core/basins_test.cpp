// Basins of attraction (core/analysis/attractors.h): the two coexisting period-1 motions of the
// impact oscillator told apart by their section points, each cell's attractor that of a plain run
// from its initial state, ids independent of the thread count, and sweeps over other fields
// refused with the field named.
#include <gtest/gtest.h>

#include <cmath>

#include "core/analysis/attractors.h"
#include "core/analysis/checked_run.h"
#include "io/sweep_json.h"
#include "tests/core/impact_oscillator.h"
#include "tests/core/scenes.h"

namespace vibro {
namespace {

using testing::impact_oscillator;

constexpr double kOmega = 6.8;  // inside 5.8 … 7.8 rad/s, where two period-1 motions coexist

SimOptions options() {
  SimOptions o;
  o.rtol = 1e-9;
  o.atol = 1e-12;
  return o;
}

SweepSpec basins(int n, int transient = 100, int record = 8) {
  SweepSpec s;
  s.axis = {"model.pellets[0].phi0", 0.05, 1.5, n};
  s.axis2 = SweepAxis{"model.pellets[0].dphi0", -7.0, 7.0, n};
  s.transient = transient;
  s.record = record;
  s.classify_attractor = true;
  return s;
}

SweepResult run(const SweepSpec& spec, int threads) {
  const Model m = impact_oscillator(kOmega);
  EXPECT_FALSE(validate_sweep(m, spec));
  SweepControl c;
  c.threads = threads;
  return run_sweep(m, options(), spec, c);
}

// The state of a plain run from (phi0, dphi0) at the end of the sweep's runs.
std::pair<double, double> plain_run_end(const SweepSpec& spec, double phi0, double dphi0) {
  Model m = impact_oscillator(kOmega);
  m.pellets[0].phi0 = phi0;
  m.pellets[0].dphi0 = dphi0;
  SimOptions o = options();
  o.t_end = (spec.transient + spec.record) * 2.0 * M_PI / kOmega;
  const RunResult r = simulate(m, o);
  return {wrap_angle(r.summary.final[0].phi), r.summary.final[0].dphi};
}

TEST(Basins, BothCoexistingPeriodOneMotionsAreFound) {
  const SweepResult r = run(basins(8), 2);
  ASSERT_TRUE(r.classified);
  // The slow and the fast period-1 motion, on the stop's side the pellet starts on (φ > 0),
  // told apart by their section points, not by their period.
  std::vector<Attractor> period_one;
  for (const Attractor& a : r.attractors)
    if (a.period == 1 && a.cells > 0 && a.section[0].first > 0.0) period_one.push_back(a);
  ASSERT_EQ(period_one.size(), 2u);
  EXPECT_GT(std::abs(period_one[0].section[0].second - period_one[1].section[0].second), 1.0);
  long cells = 0;
  for (const Attractor& a : r.attractors) cells += a.cells;
  long labelled = 0;
  for (const SweepRun& run : r.runs) labelled += run.attractor >= 0 ? 1 : 0;
  EXPECT_EQ(cells, labelled);
  for (std::size_t k = 0; k < r.attractors.size(); ++k) EXPECT_EQ(r.attractors[k].id, int(k));
}

// Every cell, each of whose runs ended where its section settled, before the sweep's end.
TEST(Basins, EachCellsAttractorIsThatOfAPlainRunFromIt) {
  const SweepSpec spec = basins(6);
  const SweepResult r = run(spec, 2);
  ASSERT_TRUE(r.classified);
  int checked = 0;
  for (std::size_t k = 0; k < r.runs.size(); ++k) {
    const SweepRun& run = r.runs[k];
    if (run.attractor < 0) continue;
    // Named copies, not a structured binding: clang 14 (the sanitizer build) cannot capture one.
    const std::pair<double, double> end = plain_run_end(spec, run.value, run.value2);
    const double phi = end.first, dphi = end.second;
    // The plain run's last state is a state of the cell's attractor, and of no other one.
    auto distance = [&](const Attractor& a) {
      double d = 1e300;
      for (const auto& s : a.section)
        d = std::min(d, std::abs(s.first - phi) + std::abs(s.second - dphi) / 4.0);
      return d;
    };
    int nearest = 0;
    for (const Attractor& a : r.attractors)
      if (distance(a) < distance(r.attractors[nearest])) nearest = a.id;
    EXPECT_EQ(nearest, run.attractor) << "phi0 " << run.value << " dphi0 " << run.value2;
    EXPECT_LT(distance(r.attractors[run.attractor]), 1e-3);
    ++checked;
  }
  EXPECT_GE(checked, 30);
}

// A run that classifies ends once its last record + 1 section points repeat: its record is
// those points, at their own times, and its period and attractor are read off them.
TEST(Basins, ARunEndsOnceItsSectionHasSettled) {
  const SweepSpec spec = basins(4);
  const SweepResult r = run(spec, 1);
  const double T = 2.0 * M_PI / kOmega;
  int early = 0;
  for (const SweepRun& run : r.runs) {
    ASSERT_EQ(run.points.size(), std::size_t(spec.record + 1));
    const double last = run.points.back().t;
    EXPECT_NEAR(run.points.front().t, last - spec.record * T, 1e-9);
    EXPECT_GE(last, 20 * T - 1e-9);  // not before its fewest periods
    if (last < (spec.transient + spec.record) * T - 1e-9) {
      ++early;
      EXPECT_GT(run.period, 0);
      EXPECT_GE(run.attractor, 0);
      EXPECT_TRUE(run.trusted);  // checked over the time it ran
    }
  }
  EXPECT_GE(early, 12) << "of " << r.runs.size();
}

// A run ends once within about 1e-4 of its attractor (kSettleFloor), not 1e-5: sooner, by
// log(10)/log(1/|multiplier|) periods, its states still within the 1e-3 attractors are told
// apart by (each cell's attractor that of a plain run: above).
TEST(Basins, ARunEndsOnceWithinTheSettleFloorOfItsAttractor) {
  const SweepSpec spec = basins(6);
  const SweepResult r = run(spec, 1);
  const double T = 2.0 * M_PI / kOmega;
  double periods = 0.0;
  for (const SweepRun& run : r.runs) periods += run.points.back().t / T;
  periods /= static_cast<double>(r.runs.size());
  // At a floor of 1 (1e-5 rad and 1e-5·sqrt(g/R)) these runs went 63.6 periods on average; at
  // kSettleFloor, 52.7.
  EXPECT_LT(periods, 58.0);
}

// The driver's side of it: a run with a settle window ends at the stop where it settled, its
// check run over the same time.
TEST(Basins, ARunWithASettleWindowEndsAtTheStopWhereItSettled) {
  Model m = impact_oscillator(kOmega);
  SimOptions o = options();
  const double T = 2.0 * M_PI / kOmega;
  o.t_end = 200 * T;
  for (int k = 0; k <= 200; ++k) o.stops.push_back(k * T);
  o.settle_window = 9;
  const RunResult r = simulate(m, o);
  ASSERT_TRUE(r.settled);
  EXPECT_EQ(r.stats.termination, Termination::completed);
  EXPECT_LT(r.stats.t_reached, 150 * T);
  EXPECT_EQ(r.stops.back().t, r.stats.t_reached);
  EXPECT_GE(r.stats.trusted_until, r.stats.t_reached);
  o.settle_window = 0;
  const RunResult plain = simulate(m, o);
  EXPECT_FALSE(plain.settled);
  EXPECT_EQ(plain.stats.t_reached, o.t_end);
}

TEST(Basins, OneThreadAndTwoGiveTheSameOutput) {
  const SweepSpec spec = basins(5, 60, 6);
  SweepResult one = run(spec, 1);
  SweepResult two = run(spec, 2);
  one.wall_ms = two.wall_ms = 0.0;
  one.threads = two.threads = 1;
  EXPECT_EQ(sweep_result_csv(spec, one), sweep_result_csv(spec, two));
  EXPECT_EQ(sweep_result_json(spec, one).dump(), sweep_result_json(spec, two).dump());
}

// The paper scene's basins: from most starts the pellets come to rest, the forced one against the
// fixed limiter and the other where friction holds it, a different angle from each start. Those
// runs are one attractor, "at rest", numbered first, not one per angle (there were 48 here).
TEST(Basins, RunsAtRestAreOneAttractorWhereverThePelletsRest) {
  const Scene paper = testing::preset("paper");
  SweepSpec spec;
  spec.axis = {"model.pellets[0].phi0", 0.0, 0.7, 10};
  spec.axis2 = SweepAxis{"model.pellets[0].dphi0", -10.0, 50.0, 10};
  spec.transient = 60;
  spec.record = 8;
  spec.classify_attractor = true;
  ASSERT_FALSE(validate_sweep(paper.model, spec));
  SweepControl control;
  control.threads = 2;
  const SweepResult r = run_sweep(paper.model, paper.sim, spec, control);
  // Attractors whose section is a state with every pellet still: rest states.
  int still = 0;
  for (const Attractor& a : r.attractors) {
    bool moves = a.section.empty() ? !a.at_rest : false;
    for (const auto& s : a.section) moves = moves || s.second != 0.0;
    still += moves ? 0 : 1;
  }
  EXPECT_EQ(still, 1);
  ASSERT_FALSE(r.attractors.empty());
  const Attractor& rest = r.attractors.front();
  EXPECT_TRUE(rest.at_rest);
  EXPECT_EQ(rest.period, 1);
  EXPECT_EQ(rest.impacts_per_period, 0.0);
  EXPECT_TRUE(rest.section.empty());
  long resting = 0;
  for (const SweepRun& run : r.runs) {
    EXPECT_EQ(run.rests, run.attractor == 0);
    if (run.rests) {
      EXPECT_TRUE(run.at_rest && run.impacts_per_period == 0.0);
    }
    resting += run.rests ? 1 : 0;
  }
  EXPECT_EQ(rest.cells, resting);
  EXPECT_GE(resting, 50);
  const auto j = sweep_result_json(spec, r);
  EXPECT_EQ(j["attractors"][0]["at_rest"], true);
  for (std::size_t k = 1; k < r.attractors.size(); ++k) EXPECT_FALSE(r.attractors[k].at_rest);
}

TEST(Basins, ClassifyingAnotherFieldIsRefusedNamingIt) {
  SweepSpec spec = basins(3);
  spec.axis2 = SweepAxis{"model.pellets[0].Omega", 6.0, 7.0, 3};
  const auto e = validate_sweep(impact_oscillator(kOmega), spec);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->field, "sweep.parameter2.parameter");
  EXPECT_NE(e->message.find("model.pellets[0].Omega"), std::string::npos) << e->message;
  spec = basins(3);
  spec.continuation = Continuation::forward;
  ASSERT_TRUE(validate_sweep(impact_oscillator(kOmega), spec));
  EXPECT_EQ(validate_sweep(impact_oscillator(kOmega), spec)->field, "sweep.continuation");
}

TEST(Basins, TheResultListsTheAttractorsAndTheColumns) {
  const SweepSpec spec = basins(3, 60, 4);
  const SweepResult r = run(spec, 1);
  const auto j = sweep_result_json(spec, r);
  ASSERT_TRUE(j.contains("attractors"));
  EXPECT_EQ(j["points"]["attractor"].size(), j["points"]["phi"].size());
  EXPECT_EQ(j["runs"]["attractor"].size(), r.runs.size());
  const auto& a = j["attractors"][0];
  for (const char* key : {"id", "period", "impacts_per_period", "section", "cells"})
    EXPECT_TRUE(a.contains(key)) << key;
  EXPECT_NE(sweep_result_csv(spec, r).find(",lyapunov,attractor\n"), std::string::npos);
  EXPECT_EQ(read_sweep(sweep_to_json(spec)).classify_attractor, true);
}

}  // namespace
}  // namespace vibro
