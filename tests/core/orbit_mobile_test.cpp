// Periodic motions with a mobile limiter (MODEL.md, "Periodic motions with a mobile limiter"):
// the armed set is part of the section's state. On the paper scene: its start comes to rest,
// another start reaches a stable period-6 motion with the mobile limiter disarmed on the section;
// the motion found is checked against plain runs and its Jacobian against differences of the map.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>
#include <variant>

#include "core/analysis/checked_run.h"
#include "core/analysis/periodic_orbit.h"
#include "io/presets.h"
#include "io/scene_json.h"

namespace vibro {
namespace {

Model paper() {
  const SceneOrError s = scene_from_text(*preset_json("paper"));
  return std::get<Scene>(s).model;
}

// The start a scan of random starts found to reach the period-6 motion (docs/ORBITS.md).
Model paper_from_another_start() {
  Model m = paper();
  m.pellets[0].phi0 = 2.182553368298441;
  m.pellets[0].dphi0 = -1.3300469552800571;
  m.pellets[1].phi0 = 0.3178501259569786;
  m.pellets[1].dphi0 = -1.5648543617682122;
  return m;
}

SimOptions options() {
  SimOptions o;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.check = false;
  return o;
}

Vec state_of(const std::vector<PhasePoint>& s) {
  Vec x(2 * s.size());
  for (std::size_t i = 0; i < s.size(); ++i) x.segment(2 * i, 2) << s[i].phi, s[i].dphi;
  return x;
}

Vec final_of(const RunResult& r) {
  Vec y(2 * r.summary.final.size());
  for (std::size_t i = 0; i < r.summary.final.size(); ++i)
    y.segment(2 * i, 2) << r.summary.final[i].phi, r.summary.final[i].dphi;
  return y;
}

PeriodicOrbit period_six() {
  OrbitSpec spec;
  spec.periods = 6;
  spec.transient = 100;
  return find_periodic_orbit(paper_from_another_start(), options(), spec);
}

// Before, every orbit search on a scene with a mobile limiter was refused ("fixed limiters only").
TEST(MobileLimiterOrbit, IsSoughtNotRefused) {
  EXPECT_FALSE(validate_orbit(paper(), {}));
  OrbitSpec spec;
  spec.guess = {{1.4, 3.4}, {1.1, 1.1}};
  spec.armed = {false, true};
  EXPECT_FALSE(validate_orbit(paper(), spec));
  spec.armed = {false};
  EXPECT_EQ(validate_orbit(paper(), spec)->field, "periodic_orbit.armed");
  spec.armed = {true, false};  // limiter 1 is fixed
  EXPECT_EQ(validate_orbit(paper(), spec)->field, "periodic_orbit.armed[1]");
  OrbitSpec no_guess;
  no_guess.armed = {false, true};  // the run to the guess gives the armed set
  EXPECT_EQ(validate_orbit(paper(), no_guess)->field, "periodic_orbit.armed");
}

// The paper's own start comes to rest (pellet 1 on the left limiter at 3π/2, pellet 2 held by
// friction near the bottom): the page's default search finds that rest state and says so.
TEST(MobileLimiterOrbit, ThePaperStartComesToRest) {
  const PeriodicOrbit o = find_periodic_orbit(paper(), options(), {});
  ASSERT_TRUE(o.converged) << o.message;
  EXPECT_TRUE(o.at_rest);
  EXPECT_NEAR(o.state[0].phi, 1.5 * M_PI, 1e-12);
  EXPECT_EQ(o.impacts_per_period, 0.0);
}

// The period-6 motion: found, admissible, stable, the mobile limiter disarmed on the section;
// a plain run from it returns to it after six periods, and the long run it was found from passes
// through it every six periods.
TEST(MobileLimiterOrbit, ThePaperScenesPeriodSixMotionIsAMotionOfPlainRuns) {
  const PeriodicOrbit o = period_six();
  ASSERT_TRUE(o.converged) << o.message;
  EXPECT_TRUE(o.admissible) << o.message;
  EXPECT_FALSE(o.at_rest);
  EXPECT_TRUE(o.stable);
  ASSERT_EQ(o.armed.size(), 2u);
  EXPECT_FALSE(o.armed[0]);
  EXPECT_TRUE(o.armed[1]);
  EXPECT_GT(o.impacts_per_period, 1.0);
  const Vec x = state_of(o.state);

  const auto once = std::get<OrbitReturn>(orbit_return(paper(), options(), o));
  EXPECT_FALSE(once.model.limiters[0].armed);
  const RunResult back = simulate(once.model, once.options);
  ASSERT_EQ(back.stats.termination, Termination::completed);
  EXPECT_LT((final_of(back) - x).lpNorm<Eigen::Infinity>(), 1e-7);
  EXPECT_EQ(back.summary.armed, o.armed);

  // Started with the mobile limiter armed, the same state is another motion.
  Model armed = once.model;
  armed.limiters[0].armed = true;
  SimOptions o6 = once.options;
  const RunResult other = simulate(armed, o6);
  EXPECT_GT((final_of(other) - x).lpNorm<Eigen::Infinity>(), 1e-3);

  SimOptions longer = options();
  for (int k : {106, 112}) {
    longer.t_end = k * o.period;
    const RunResult run = simulate(paper_from_another_start(), longer);
    EXPECT_LT((final_of(run) - x).lpNorm<Eigen::Infinity>(), 1e-6) << k << " periods";
    EXPECT_EQ(run.summary.armed, o.armed);
  }
}

// Its multipliers are those of the exact Jacobian (saltations through the mobile limiter's
// impacts and the collisions), which central differences of the map confirm.
TEST(MobileLimiterOrbit, MultipliersMatchDifferencesOfTheMap) {
  const PeriodicOrbit o = period_six();
  ASSERT_TRUE(o.converged) << o.message;
  ASSERT_TRUE(o.exact_jacobian) << o.jacobian_note;
  const Model section = armed_as(paper_from_another_start(), o.armed);
  SimOptions tight = options();
  tight.rtol = 1e-12;
  tight.atol = 1e-14;
  const Vec x = state_of(o.state);
  const MapPoint p = stroboscopic_map(section, tight, 6, x);
  ASSERT_TRUE(p.ok) << p.run.stats.message;
  Mat D(x.size(), x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    const double h = 1e-6;
    Vec xp = x, xm = x;
    xp[k] += h;
    xm[k] -= h;
    const MapPoint up = stroboscopic_map(section, tight, 6, xp);
    const MapPoint down = stroboscopic_map(section, tight, 6, xm);
    ASSERT_TRUE(up.ok && down.ok);
    D.col(k) = (up.image - down.image) / (2.0 * h);
  }
  EXPECT_LT((D - p.jacobian).lpNorm<Eigen::Infinity>(), 1e-4 * (1.0 + D.lpNorm<Eigen::Infinity>()))
      << "exact\n"
      << p.jacobian << "\ndifferenced\n"
      << D;
  const Eigen::VectorXcd exact = Eigen::EigenSolver<Mat>(p.jacobian, false).eigenvalues();
  const Eigen::VectorXcd diff = Eigen::EigenSolver<Mat>(D, false).eigenvalues();
  for (Eigen::Index k = 0; k < exact.size(); ++k) {
    double nearest = INFINITY;
    for (Eigen::Index j = 0; j < diff.size(); ++j)
      nearest = std::min(nearest, std::abs(exact[k] - diff[j]));
    EXPECT_LT(nearest, 1e-4) << exact[k];
  }
}

// A state with the pellets swapped is a motion the scene never reaches: a guess is refused and
// the map does not run from one. (Before, a search from the period-6 motion's neighbourhood
// converged to such a motion, pellet 2 above pellet 1, and vouched for it.)
TEST(MobileLimiterOrbit, PelletsKeepTheirOrderOnTheSection) {
  OrbitSpec spec;
  spec.periods = 6;
  spec.transient = 0;
  spec.guess = {{0.344, 1.99}, {0.763, 0.895}};
  spec.armed = {false, true};
  const auto e = validate_orbit(paper(), spec);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->field, "periodic_orbit.guess[1].phi");
  EXPECT_NE(e->message.find("order"), std::string::npos);
  Vec x(4);
  x << 0.344, 1.99, 0.763, 0.895;
  EXPECT_FALSE(stroboscopic_map(paper(), options(), 1, x).ok);
}

}  // namespace
}  // namespace vibro
