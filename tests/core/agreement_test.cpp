// Regressions the differential tests found: scenes where one method at one tolerance listed
// other events than the rest. Every method at every tolerance must now list the same events.
#include <gtest/gtest.h>

#include <cmath>

#include "core/analysis/checked_run.h"
#include "scenes.h"

namespace vibro {
namespace {

// Kind, pellets and limiter of every event, and the largest time difference.
void expect_same_events(const RunResult& a, const RunResult& b, double dt,
                        const std::string& what) {
  ASSERT_EQ(a.events.size(), b.events.size()) << what;
  double worst = 0.0;
  for (std::size_t k = 0; k < a.events.size(); ++k) {
    const Event& x = a.events[k];
    const Event& y = b.events[k];
    ASSERT_TRUE(x.kind == y.kind && x.pellets == y.pellets && x.limiter == y.limiter)
        << what << ": event " << k << " is " << event_kind_name(x.kind) << " at t = " << x.t
        << ", against " << event_kind_name(y.kind) << " at t = " << y.t;
    worst = std::max(worst, std::abs(x.t - y.t));
  }
  EXPECT_LE(worst, dt) << what;
}

void expect_every_method_agrees(const Model& model, double t_end) {
  SimOptions reference = testing::recorded(model, t_end, Method::dop853, 1e-12, 1e-14);
  const RunResult ref = simulate(model, reference);
  for (Method m : {Method::dopri5, Method::dop853, Method::radau5, Method::automatic}) {
    for (double rtol : {1e-8, 1e-10, 1e-12}) {
      const RunResult run = simulate(model, testing::recorded(model, t_end, m, rtol, rtol * 1e-2));
      expect_same_events(run, ref, 1e4 * rtol, testing::method_at(m, rtol));
    }
  }
}

// A held body is released at a root of capacity − |a_free|, where the stick test is decided by
// round-off: dop853 at 1e-10 once landed exactly on |a_free| = capacity, kept the body stuck, and
// every later event was wrong. The release watch's crossing now decides.
TEST(Agreement, AReleaseIsTakenWhereverItsRootLands) {
  expect_every_method_agrees(testing::preset("rest-in-cone").model, 10.0);
  Model tiny = testing::preset("paper").model;
  tiny.R = 1e-3;  // pellets pressed together and stuck, released by the force again and again
  expect_every_method_agrees(tiny, 12.0);
}

// Three pellets on R = 1.2 mm (g/R = 8e3 rad/s²) in a cascade of collisions: the middle one,
// knocked onto the one ahead 7e-9 rad away at 0.8 rad/s, meets it 8e-9 s later, but pressed
// back, passes and parts from it again before the step's next sample 1e-4 s on. DOP853 at
// rtol 1e-6 … 1e-9 never listed that collision (differential trust scan, seed 5, scene 69).
TEST(Agreement, AMeetingBetweenTwoSamplesIsFound) {
  Model m;
  m.g = 9.81;
  m.R = 0.0012241572788504597;
  m.alpha0 = 0.0;
  m.friction = FrictionLaw::bilateral;
  m.k_c = 0.3194913864135742;
  m.limiters = {{-1.7236970602498884, 0.8374481201171875, false, -1, {}}};
  m.pellets = {{1.8193861678960277,
                -1.4821250467201632,
                0.0,
                {25.876246614927027, 1.0646746444021653, 4.795589461790128}},
               {0.012298775380389804, 0.5930633378913805, 65.61650866648252, {}},
               {0.04496079052183319,
                0.5930633398913806,
                -799.0049877778455,
                {0.2991178024951093, 98.20079885558984, 5.156308639328908}}};
  const double t_end = 0.0209;  // the steps, and so the samples, as the scan had them
  const RunResult ref = simulate(m, testing::recorded(m, t_end, Method::dop853, 1e-13, 1e-15));
  for (Method method : {Method::dopri5, Method::dop853, Method::radau5}) {
    for (double rtol : {1e-6, 1e-7, 1e-8, 1e-9}) {
      const RunResult run = simulate(m, testing::recorded(m, t_end, method, rtol, rtol * 1e-3));
      expect_same_events(run, ref, 1e4 * rtol, testing::method_at(method, rtol));
    }
  }
}

// Two pellets parting after a collision at 8e-5 rad/s are pressed together again 5e-4 s
// later, inside one step of 8e-3 s whose samples all found them apart and parting: DOP853 at
// rtol 1e-10 and its shadow missed that collision, and vouched for the events after it
// (differential trust scan, seed 3, scene 604). A quadratic prediction from the interval's start
// marches to it.
TEST(Agreement, APairPressedTogetherWithinOneStepMeetsAgain) {
  Model m;
  m.g = 9.81;
  m.R = 0.7610421162704857;
  m.alpha0 = 0.1488933563232422;
  m.mu_s = 0.2753329798879047;
  m.k_c = 1.0;
  m.limiters = {{1.1775699392003371, 0.6963062286376953, false, -1, {0, 2}},
                {-0.08852746937586886, 0.001514434814453125, false, -1, {}}};
  m.pellets = {{0.032209442488323074,
                0.1479800252478801,
                0.0,
                {0.8624261792941151, 3.612024620404413, 1.5636956735384728}},
               {0.08832313703033735,
                0.1479800272478801,
                0.0,
                {2.423097767964952, 22.128482357633665, 3.9616312190761747}},
               {0.022498412271316798,
                -1.596754157939899,
                -0.9797200927430944,
                {0.26436041635218843, 0.46502027182055916, 4.086033465706229}}};
  const double t_end = 1.265706649071372;  // the steps, and so the samples, as the scan had them
  const RunResult ref = simulate(m, testing::recorded(m, t_end, Method::dop853, 1e-13, 1e-15));
  for (double rtol : {1e-8, 1e-9, 1e-10}) {
    RunResult run = simulate(m, testing::recorded(m, t_end, Method::dop853, rtol, rtol * 1e-3));
    RunResult head = ref;
    // The first 0.06 s: the collisions of the pair, and the turn after them.
    std::erase_if(run.events, [](const Event& e) { return e.t > 0.06; });
    std::erase_if(head.events, [](const Event& e) { return e.t > 0.06; });
    expect_same_events(run, head, 1e4 * rtol, testing::method_at(Method::dop853, rtol));
  }
}

}  // namespace
}  // namespace vibro

namespace vibro {
namespace {

// Radau IIA's dense output (the collocation polynomial) is of order 3 where its steps are of
// order 5: roots found on it erred by 2e-8 s on the paper scene and 2e-6 s on the chatter scene
// at rtol 1e-10, 100 to 1000 times the error of its steps. Polished on precise states, the
// event times are as accurate as DOP853's at the same tolerance.
TEST(Agreement, RadauEventTimesAreAsAccurateAsItsSteps) {
  for (const char* name : {"paper", "chatter"}) {
    const Model model = testing::preset(name).model;
    const double t_end = testing::preset(name).sim.t_end;
    const RunResult ref =
        simulate(model, testing::recorded(model, t_end, Method::dop853, 1e-13, 1e-15));
    const RunResult run =
        simulate(model, testing::recorded(model, t_end, Method::radau5, 1e-10, 1e-12));
    ASSERT_EQ(run.events.size(), ref.events.size()) << name;
    double worst = 0.0;
    for (std::size_t k = 0; k < run.events.size(); ++k)
      worst = std::max(worst, std::abs(run.events[k].t - ref.events[k].t));
    EXPECT_LT(worst, 2e-9) << name;
  }
}

}  // namespace
}  // namespace vibro

namespace vibro {
namespace {

// Under the bilateral law the friction is μ|N|, whose kink where the normal force N changes sign
// an integrator's error estimate does not see: DOP853 stepped over it and erred by 200 times its
// tolerance at rtol 1e-12 (and a reference at 1e-13 put a collision 2e-10 s off: trust scan,
// seed 5, scene 627). An interval keeps one side of N, and the normal watch ends it at the kink.
TEST(Agreement, TheKinkOfTheBilateralFrictionIsNotSteppedOver) {
  Model m;
  m.g = 9.81;
  m.R = 0.4440552433212397;
  m.alpha0 = 0.5230987092141564;
  m.friction = FrictionLaw::bilateral;
  m.pellets = {{0.2578851740722063,
                1.868645998525996,
                7.036735810884636,
                {1.5158514617388013, 58.479920553210626, 0.21682221335042517}}};
  const double t_end = 0.36629231181604893;
  auto normal = [&](double phi, double dphi) { return m.g * std::cos(phi) + m.R * dphi * dphi; };
  const RunResult ref = simulate(m, testing::recorded(m, t_end, Method::dop853, 1e-13, 1e-16));
  const FinalState& end = ref.summary.final[0];
  ASSERT_GT(normal(m.pellets[0].phi0, m.pellets[0].dphi0), 0.0);
  ASSERT_LT(normal(end.phi, end.dphi), 0.0) << "the normal force must change sign on the way";
  const double T0 = std::sqrt(m.R / m.g);
  for (Method method : {Method::dopri5, Method::dop853, Method::radau5}) {
    for (double rtol : {1e-8, 1e-10, 1e-12}) {
      const RunResult run = simulate(m, testing::recorded(m, t_end, method, rtol, rtol * 1e-3));
      const FinalState& f = run.summary.final[0];
      const std::string what = testing::method_at(method, rtol);
      EXPECT_LE(std::abs(f.phi - end.phi), 10.0 * rtol * (1.0 + std::abs(end.phi))) << what;
      EXPECT_LE(T0 * std::abs(f.dphi - end.dphi), 10.0 * rtol) << what;
    }
  }
}

}  // namespace
}  // namespace vibro

namespace vibro {
namespace {

// A pellet released from rest under forcing at 741 rad/s: DOP853's first step after the
// release, 3.8 ms, came after rejected steps three and nine times as long, and its estimate (0.02
// of the tolerance) was far below what the rejections predicted (100). The step erred by a hundred
// tolerances and moved the next stick by 9e-9 s at rtol 1e-8 and 1e-9 alike (trust scan, seed 3,
// scene 565). After a rejection an estimate is taken no lower than the error model predicts.
TEST(Agreement, AStepAfterARejectionIsNotTakenOnAnIncredibleEstimate) {
  Model m;
  m.g = 9.81;
  m.R = 1.5414828248167514;
  m.alpha0 = 0.11922836303710938;
  m.friction = FrictionLaw::bilateral;
  m.pellets = {{0.043529477570106744,
                -0.10372945866831396,
                -0.16444092931143545,
                {0.022703333597181505, 741.0675352709418, 5.338055402131093}}};
  const double t_end = 0.339142386254035;
  const double T0 = std::sqrt(m.R / m.g);
  const RunResult ref = simulate(m, testing::recorded(m, t_end, Method::dop853, 1e-13, 1e-16));
  ASSERT_GE(testing::events_of(ref, EventKind::release).size(), 20u);
  for (Method method : {Method::dopri5, Method::dop853}) {
    for (double rtol : {1e-7, 1e-8, 1e-9}) {
      const RunResult run = simulate(m, testing::recorded(m, t_end, method, rtol, rtol * 1e-3));
      ASSERT_EQ(run.events.size(), ref.events.size()) << testing::method_at(method, rtol);
      for (std::size_t k = 0; k < run.events.size(); ++k)
        ASSERT_LE(std::abs(run.events[k].t - ref.events[k].t), 0.1 * rtol * (T0 + ref.events[k].t))
            << testing::method_at(method, rtol) << ", event " << k;
    }
  }
}

}  // namespace
}  // namespace vibro

namespace vibro {
namespace {

// A pellet released 1e-6 rad from the bottom swings onto one resting there a turn down. DOP853
// took the whole quarter swing (ωh = 2.75) in one step on an estimate of 0.03 of the tolerance
// and put the collision 7.6e-5 s off at rtol 1e-6 and 1e-7 alike, while its check vouched for
// 4e-9 s (trust scan, seed 4, scene 706). No step spans more than a third of a swing now.
TEST(Agreement, NoStepSpansAThirdOfASwing) {
  Model m;
  m.g = 9.81;
  m.R = 0.0055542457521309575;
  m.alpha0 = 0.0;
  m.friction = FrictionLaw::bilateral;
  m.k_c = 0.6047582626342773;
  m.limiters = {{1.3981336064709717, 1.0, false, -1, {}},
                {-2.3198583202793035, 1.0, false, -1, {1}}};
  m.pellets = {{0.13607746227724682, -6.283185307179586, 0.0, {}},
               {1.46582908890532, 1e-6, 0.0, {}}};
  const double t_end = 0.0654677716794234;
  const RunResult ref = simulate(m, testing::recorded(m, t_end, Method::dop853, 1e-13, 1e-16));
  ASSERT_EQ(ref.events.size(), 1u);
  for (Method method : {Method::dopri5, Method::dop853, Method::radau5}) {
    for (double rtol : {1e-6, 1e-7}) {
      SimOptions o = testing::recorded(m, t_end, method, rtol, rtol * 1e-3);
      o.check = true;
      const RunResult run = simulate(m, o);
      ASSERT_EQ(run.events.size(), 1u) << testing::method_at(method, rtol);
      const double error = std::abs(run.events[0].t - ref.events[0].t);
      EXPECT_LT(error, 1e-6) << testing::method_at(method, rtol);
      EXPECT_GE(10.0 * run.stats.event_time_error, error) << testing::method_at(method, rtol);
    }
  }
}

}  // namespace
}  // namespace vibro

namespace vibro {
namespace {

// Two elastic pellets (k_c = 1) pressed together by a third and a limiter bounced 1e-8 s apart
// and 1e-15 rad high: thirteen collisions at one tolerance, thirty-four at another, and the
// events after them wrong (trust scan, seed 6, scene 72). Pellets that would part by less than
// the round-off of the gap move on together.
TEST(Agreement, PressedPelletsThatWouldPartByRoundOffMoveOnTogether) {
  Model m;
  m.g = 9.81;
  m.R = 0.4518864269488188;
  m.alpha0 = 0.0;
  m.k_c = 1.0;
  m.limiters = {{0.016592159381465965, 0.07467937469482422, false, -1, {}},
                {-0.2723415109742282, 0.0977163314819336, false, -1, {}},
                {2.782904802172471, 0.8026266098022461, true, 0, {}}};
  m.pellets = {{0.1610528103101952,
                -2.663350174516634,
                0.0,
                {1.9756122257874995, 63.806634332934166, 6.238208511109783}},
               {1.444871217161532,
                6.292862568790662,
                15.452045642994527,
                {40.398329790119476, 0.20618390504643377, 3.415264413528516}},
               {1.0914789529489728, 0.0, 0.0, {}},
               {0.05834742957871862,
                0.016592159381465965,
                -12.43150855709999,
                {0.6934763418143586, 4.500949083290005, 1.234524968063044}}};
  const double t_end = 0.7251350529270345;
  const RunResult ref = simulate(m, testing::recorded(m, t_end, Method::dop853, 1e-13, 1e-15));
  for (Method method : {Method::dopri5, Method::dop853}) {
    for (double rtol : {1e-8, 1e-10, 1e-12}) {
      const RunResult run = simulate(m, testing::recorded(m, t_end, method, rtol, rtol * 1e-3));
      expect_same_events(run, ref, 1e4 * rtol, testing::method_at(method, rtol));
    }
  }
}

}  // namespace
}  // namespace vibro
