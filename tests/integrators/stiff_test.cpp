// Stiff problems: RADAU5 is efficient and accurate, the explicit methods detect stiffness, and
// "auto" switches to RADAU5 and back.
#include <gtest/gtest.h>

#include "core/integrators/auto_switch.h"
#include "core/integrators/dop853.h"
#include "core/integrators/dopri5.h"
#include "core/integrators/radau5.h"
#include "core/integrators/stepper.h"
#include "core/integrators/stiffness.h"
#include "tests/integrators/test_problems.h"

namespace vibro::testing {
namespace {

using integrators::AutoSwitch;
using integrators::Dop853;
using integrators::Dopri5;
using integrators::Radau5;

StepperOptions tolerances(double rtol, double atol) {
  StepperOptions o;
  o.rtol = rtol;
  o.atol = atol;
  return o;
}

// Van der Pol, mu = 1e3, over more than one relaxation period (t = 2 in Hairer's scaling).
Vec van_der_pol_radau5(double rtol, long* steps) {
  const VanDerPol sys(1e-6);
  Radau5 s(tolerances(rtol, rtol));
  s.start(sys, 0.0, VanDerPol::initial());
  const RunResult run = run_to(s, 2.0);
  EXPECT_EQ(run.status, StepStatus::ok);
  if (steps) *steps = s.stats().steps;
  return s.y();
}

TEST(IntegratorsStiff, Radau5SolvesVanDerPolQuicklyAndAccurately) {
  const Vec reference = van_der_pol_radau5(1e-12, nullptr);
  EXPECT_LT((reference - VanDerPol::reference_at_2()).norm(), 1e-8);
  long steps = 0;
  const Vec y = van_der_pol_radau5(1e-6, &steps);
  EXPECT_LT(steps, 2000);
  EXPECT_LT((y - reference).norm(), 1e-4);
}

TEST(IntegratorsStiff, Radau5SolvesRobertson) {
  const Robertson sys;
  Radau5 s(tolerances(1e-8, 1e-12));
  s.start(sys, 0.0, Robertson::initial());
  ASSERT_EQ(run_to(s, 40.0).status, StepStatus::ok);
  // Reference at t = 40 (SUNDIALS cvRoberts_dns).
  EXPECT_NEAR(s.y()[0], 0.7158270687193687, 1e-6);
  EXPECT_NEAR(s.y()[1], 9.185534764529634e-06, 1e-10);
  EXPECT_NEAR(s.y()[2], 0.2841637457458667, 1e-6);
  EXPECT_LT(s.stats().steps, 200);
  ASSERT_EQ(run_to(s, 4e10).status, StepStatus::ok);  // and on to the far end, cheaply
  EXPECT_NEAR(s.y().sum(), 1.0, 1e-8);
  EXPECT_LT(s.stats().steps, 1000);
}

template <class Explicit>
void expect_stiffness_detected() {
  const VanDerPol sys(1e-6);
  Explicit s(tolerances(1e-6, 1e-6));
  s.start(sys, 0.0, VanDerPol::initial());
  EXPECT_FALSE(s.stiffness_detected());
  const RunResult run = run_to(s, 2.0, 2000);
  EXPECT_EQ(run.status, StepStatus::ok);
  EXPECT_TRUE(s.stiffness_detected());
}

TEST(IntegratorsStiff, ExplicitMethodsDetectStiffness) {
  expect_stiffness_detected<Dopri5>();
  expect_stiffness_detected<Dop853>();
}

// The query the simulator uses through a plain Stepper&.
TEST(IntegratorsStiff, StiffnessQueryThroughTheInterface) {
  const VanDerPol stiff(1e-6);
  const Oscillator calm;
  for (Method m : all_methods()) {
    auto s = make_stepper(m, tolerances(1e-6, 1e-6));
    s->start(calm, 0.0, Oscillator::initial());
    ASSERT_EQ(run_to(*s, 10.0).status, StepStatus::ok);
    EXPECT_FALSE(integrators::stiffness_detected(*s)) << method_name(m);
    s->start(stiff, 0.0, VanDerPol::initial());
    ASSERT_EQ(run_to(*s, 0.3, 2000).status, StepStatus::ok);
    EXPECT_TRUE(integrators::stiffness_detected(*s)) << method_name(m);
  }
}

TEST(IntegratorsStiff, ExplicitMethodsDoNotFlagNonStiffProblems) {
  const Oscillator sys;
  Dop853 s(tolerances(1e-8, 1e-8));
  s.start(sys, 0.0, Oscillator::initial());
  ASSERT_EQ(run_to(s, 100.0).status, StepStatus::ok);
  EXPECT_FALSE(s.stiffness_detected());
  Dopri5 d(tolerances(1e-8, 1e-8));
  d.start(sys, 0.0, Oscillator::initial());
  ASSERT_EQ(run_to(d, 100.0).status, StepStatus::ok);
  EXPECT_FALSE(d.stiffness_detected());
}

TEST(IntegratorsStiff, AutoSwitchesToRadau5OnVanDerPol) {
  const VanDerPol sys(1e-6);
  const double t_end = 0.3;  // the slow stiff phase
  auto dop = make_stepper(Method::dop853, tolerances(1e-6, 1e-6));
  dop->start(sys, 0.0, VanDerPol::initial());
  ASSERT_EQ(run_to(*dop, t_end).status, StepStatus::ok);

  auto s = make_stepper(Method::automatic, tolerances(1e-6, 1e-6));
  s->start(sys, 0.0, VanDerPol::initial());
  EXPECT_EQ(s->name(), "dopri5");  // the explicit method for rtol 1e-6
  ASSERT_EQ(run_to(*s, t_end).status, StepStatus::ok);
  EXPECT_EQ(s->name(), "radau5");
  EXPECT_GE(s->stats().stiff_switches, 1);
  EXPECT_LT(s->stats().steps * 20, dop->stats().steps);
  EXPECT_LT((s->y() - dop->y()).norm(), 1e-4);

  // And on over a full period with its fast jumps, still cheaply and accurately.
  ASSERT_EQ(run_to(*s, 2.0).status, StepStatus::ok);
  EXPECT_LT(s->stats().steps, 3000);
  EXPECT_LT((s->y() - VanDerPol::reference_at_2()).norm(), 1e-4);
}

TEST(IntegratorsStiff, AutoStartsWithTheExplicitMethodForItsTolerance) {
  EXPECT_EQ(make_stepper(Method::automatic, tolerances(1e-5, 1e-7))->name(), "dopri5");
  EXPECT_EQ(make_stepper(Method::automatic, tolerances(1e-6, 1e-8))->name(), "dopri5");
  // From rtol 5e-7 down Taylor, where the system has jets (auto_explicit_for).
  EXPECT_EQ(make_stepper(Method::automatic, tolerances(5e-7, 5e-9))->name(), "taylor");
  EXPECT_EQ(make_stepper(Method::automatic, tolerances(1e-7, 1e-9))->name(), "taylor");
  EXPECT_EQ(make_stepper(Method::automatic, tolerances(1e-8, 1e-10))->name(), "taylor");
  EXPECT_EQ(make_stepper(Method::automatic, tolerances(1e-9, 1e-12))->name(), "taylor");
}

TEST(IntegratorsStiff, AutoSwitchesBackWhenTheProblemCalmsDown) {
  const StiffThenCalm sys;
  AutoSwitch s(tolerances(1e-8, 1e-8));
  s.start(sys, 0.0, StiffThenCalm::initial());
  ASSERT_EQ(run_to(s, 1.5).status, StepStatus::ok);
  EXPECT_EQ(s.name(), "radau5");
  EXPECT_EQ(s.stats().stiff_switches, 1);
  ASSERT_EQ(run_to(s, 20.0).status, StepStatus::ok);
  EXPECT_EQ(s.name(), "dop853");
  EXPECT_GE(s.stats().stiff_switches, 2);
  EXPECT_NEAR(s.y()[0], StiffThenCalm::exact(20.0)[0], 1e-6);
  // Switching stays rare: no ping-pong.
  EXPECT_LE(s.stats().stiff_switches, 4);
}

}  // namespace
}  // namespace vibro::testing
