// How far a path's instants move when its start moves (core/analysis/monodromy.h, instant_shifts):
// the first-order shifts against central differences of plain runs, over collisions, limiter
// impacts, turns, sticks and releases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/analysis/checked_run.h"
#include "core/analysis/monodromy.h"

namespace vibro {
namespace {

SimOptions tight(double t_end) {
  SimOptions o;
  o.t_end = t_end;
  o.rtol = 1e-12;
  o.atol = 1e-15;
  o.check = false;
  return o;
}

Model moved(Model m, const Vec& delta, double by) {
  for (int i = 0; i < m.size(); ++i) {
    m.pellets[i].phi0 += by * delta[2 * i];
    m.pellets[i].dphi0 += by * delta[2 * i + 1];
  }
  return m;
}

// Every instant's shift against (t(x + δ) − t(x − δ)) / 2, over the events both runs list alike.
void expect_shifts_match_differences(const Model& model, const Vec& delta, double t_end,
                                     std::size_t at_least) {
  SimOptions o = tight(t_end);
  o.keep_path = true;
  const RunResult run = simulate(model, o);
  const InstantShifts shifts = instant_shifts(model, run.path, delta, 1e-4);
  ASSERT_TRUE(shifts.unsupported.empty()) << shifts.unsupported;
  ASSERT_EQ(shifts.dt.rows(), static_cast<Eigen::Index>(run.path.size()));
  const RunResult ahead = simulate(moved(model, delta, 1.0), tight(t_end));
  const RunResult behind = simulate(moved(model, delta, -1.0), tight(t_end));
  std::size_t compared = 0, e = 0;
  for (std::size_t k = 0; k < run.path.size(); ++k) {
    if (run.path[k].events.empty()) continue;
    const Event& first = run.path[k].events.front();
    while (e < run.events.size() && run.events[e].t < first.t) ++e;
    if (e >= ahead.events.size() || e >= behind.events.size()) break;
    if (ahead.events[e].kind != first.kind || behind.events[e].kind != first.kind) break;
    const double differenced = 0.5 * (ahead.events[e].t - behind.events[e].t);
    EXPECT_NEAR(shifts.dt(static_cast<Eigen::Index>(k), 0), differenced,
                2e-2 * std::abs(differenced) + 1e-13)
        << event_kind_name(first.kind) << " at t = " << first.t;
    ++compared;
  }
  EXPECT_GE(compared, at_least);
}

TEST(InstantShifts, CollisionsLimiterImpactsAndTurnsMatchDifferences) {
  Model m;
  m.alpha0 = 0.05;
  m.k_c = 0.7;
  m.pellets = {{0.2, 0.3, 2.0, {1.0, 4.0, 0.3}}, {0.3, -0.3, 0.5, {}}};
  m.limiters = {{std::numbers::pi / 4, 0.6, false, -1, {}},
                {-std::numbers::pi / 4, 0.6, false, -1, {}}};
  Vec delta(4);
  delta << 1e-7, -2e-7, 3e-7, 1e-7;
  expect_shifts_match_differences(m, delta, 5.0, 12);
}

TEST(InstantShifts, SticksAndReleasesMatchDifferences) {
  Model m;
  m.alpha0 = 0.3;
  m.pellets = {{0.1, 0.2, 0.0, {0.25, 3.0, 0.0}}};
  m.limiters = {{1.0, 0.7, false, -1, {}}, {-1.0, 0.7, false, -1, {}}};
  Vec delta(2);
  delta << 1e-7, 0.0;  // a speed would set the pellet at rest moving
  expect_shifts_match_differences(m, delta, 2.0, 2);
}

// A path kept to a limit ends at the instant that reached it, its last interval closed there, and
// the shifts are those of the whole path's first instants.
TEST(InstantShifts, APathKeptToALimitEndsThere) {
  Model m;
  m.alpha0 = 0.05;
  m.k_c = 0.7;
  m.pellets = {{0.2, 0.3, 2.0, {1.0, 4.0, 0.3}}, {0.3, -0.3, 0.5, {}}};
  SimOptions o = tight(3.0);
  o.keep_path = true;
  const RunResult whole = simulate(m, o);
  ASSERT_GT(whole.path.size(), 5u);
  o.path_limit = 4;
  const RunResult kept = simulate(m, o);
  ASSERT_EQ(kept.path.size(), 4u);
  EXPECT_EQ(kept.path.back().t_end, whole.path[4].t);
  EXPECT_EQ(kept.events.size(), whole.events.size());
  Vec delta(4);
  delta << 1e-7, 1e-7, 1e-7, 1e-7;
  const InstantShifts a = instant_shifts(m, whole.path, delta, 1e-4);
  const InstantShifts b = instant_shifts(m, kept.path, delta, 1e-4);
  ASSERT_EQ(b.dt.rows(), 4);
  EXPECT_EQ(a.dt.topRows(4), b.dt);
  // A spent budget (the run's deadline) leaves them unknown, without a failure.
  const InstantShifts none = instant_shifts(m, whole.path, delta, 1e-4, -1.0);
  EXPECT_EQ(none.dt.rows(), 0);
  EXPECT_TRUE(none.unsupported.empty());
}

// Pellets moving together are outside what the saltations cover: no shifts, and the reason.
TEST(InstantShifts, PelletsMovingTogetherAreNamed) {
  Model m;
  m.k_c = 0.0;
  m.pellets = {{0.2, 0.3, 2.0, {}}, {0.3, 0.6, 0.0, {}}};
  SimOptions o = tight(1.0);
  o.keep_path = true;
  const RunResult run = simulate(m, o);
  const InstantShifts shifts = instant_shifts(m, run.path, Vec::Constant(4, 1e-7), 1e-4);
  EXPECT_EQ(shifts.dt.rows(), 0);
  EXPECT_NE(shifts.unsupported.find("pellets moving together"), std::string::npos)
      << shifts.unsupported;
}

}  // namespace
}  // namespace vibro
