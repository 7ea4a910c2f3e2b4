// Restarts after events: start() again behaves as a fresh start (no stale FSAL or Jacobian), keeps
// accumulating statistics and may change the dimension.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/integrators/stepper.h"
#include "tests/integrators/test_problems.h"

namespace vibro::testing {
namespace {

// y' = c (constant right-hand side).
class Drift final : public OdeSystem {
 public:
  explicit Drift(double c) : c_(c) {}
  int dimension() const override { return 1; }
  void rhs(double, const Vec&, Vec& dydt) const override { dydt[0] = c_; }
  void jacobian(double, const Vec&, Mat& dfdy, Vec& dfdt) const override {
    dfdy.setZero();
    dfdt.setZero();
  }

 private:
  double c_;
};

// y' = −y.
class Decay final : public OdeSystem {
 public:
  int dimension() const override { return 1; }
  void rhs(double, const Vec& y, Vec& dydt) const override { dydt[0] = -y[0]; }
  void jacobian(double, const Vec&, Mat& dfdy, Vec& dfdt) const override {
    dfdy(0, 0) = -1.0;
    dfdt.setZero();
  }
};

class IntegratorsRestart : public ::testing::TestWithParam<Method> {};

TEST_P(IntegratorsRestart, RestartUsesTheNewRightHandSideAndState) {
  StepperOptions o;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  const Drift drift(3.0);
  const Decay decay;
  auto s = make_stepper(GetParam(), o);
  s->start(drift, 0.0, Vec::Zero(1));
  ASSERT_EQ(run_to(*s, 1.0).status, StepStatus::ok);
  const long evals_before = s->stats().rhs_evals;
  const long steps_before = s->stats().steps;
  const long rejected_before = s->stats().rejected;

  // An "event": new state and a new right-hand side at t1 (even slightly before t(), as after
  // an event located inside the last step).
  const double t1 = s->t_prev() + 0.5 * (s->t() - s->t_prev());
  s->start(decay, t1, Vec::Constant(1, 2.0));
  EXPECT_EQ(s->t(), t1);
  EXPECT_EQ(s->y()[0], 2.0);

  // The first step is that of a fresh stepper (the drift's step-size hint is larger than HINIT's
  // guess): the same step, not rejected for a stale f.
  auto fresh = make_stepper(GetParam(), o);
  fresh->start(decay, t1, Vec::Constant(1, 2.0));
  ASSERT_EQ(s->step(t1 + 3.0), StepStatus::ok);
  ASSERT_EQ(fresh->step(t1 + 3.0), StepStatus::ok);
  EXPECT_EQ(s->t(), fresh->t());
  EXPECT_EQ(s->y()[0], fresh->y()[0]);
  EXPECT_EQ(s->stats().rejected, rejected_before);

  ASSERT_EQ(run_to(*s, t1 + 3.0).status, StepStatus::ok);
  ASSERT_EQ(run_to(*fresh, t1 + 3.0).status, StepStatus::ok);
  EXPECT_NEAR(s->y()[0], 2.0 * std::exp(-3.0), 1e-8);
  EXPECT_NEAR(s->y()[0], fresh->y()[0], 1e-9);

  // Statistics accumulate over the stepper's whole life.
  EXPECT_GT(s->stats().rhs_evals, evals_before);
  EXPECT_GT(s->stats().steps, steps_before);
}

TEST_P(IntegratorsRestart, DimensionMayChangeBetweenStarts) {
  StepperOptions o;
  o.rtol = 1e-9;
  const Oscillator osc;
  const Decay decay;
  auto s = make_stepper(GetParam(), o);
  s->start(osc, 0.0, Oscillator::initial());
  ASSERT_EQ(run_to(*s, 1.0).status, StepStatus::ok);
  s->start(decay, 1.0, Vec::Ones(1));
  ASSERT_EQ(run_to(*s, 2.0).status, StepStatus::ok);
  EXPECT_NEAR(s->y()[0], std::exp(-1.0), 1e-7);
  s->start(osc, 0.0, Oscillator::initial());
  ASSERT_EQ(run_to(*s, 3.0).status, StepStatus::ok);
  EXPECT_LT((s->y() - Oscillator::exact(3.0)).norm(), 1e-7);
}

TEST_P(IntegratorsRestart, ManyShortSegmentsStayAccurate) {
  // The simulator's pattern: restart often at the current state with the same system.
  StepperOptions o;
  o.rtol = 1e-9;
  o.atol = 1e-12;
  const Oscillator osc;
  auto s = make_stepper(GetParam(), o);
  s->start(osc, 0.0, Oscillator::initial());
  for (int k = 1; k <= 50; ++k) {
    const double t_end = 0.2 * k;
    ASSERT_EQ(run_to(*s, t_end).status, StepStatus::ok);
    const Vec y = s->y();
    s->start(osc, t_end, y);
  }
  EXPECT_LT((s->y() - Oscillator::exact(10.0)).norm(), 1e-7);
}

// Where the motion goes on smoothly (a reversal), the explicit methods keep the step size their
// controller proposed, without HINIT's evaluation; RADAU5 restarts as after an impact. The
// segments stay as accurate as with fresh starts.
TEST_P(IntegratorsRestart, ContinuingSmoothlyKeepsTheStepSize) {
  StepperOptions o;
  o.rtol = 1e-9;
  o.atol = 1e-12;
  const Oscillator osc;
  auto smooth = make_stepper(GetParam(), o);
  auto fresh = make_stepper(GetParam(), o);
  smooth->start(osc, 0.0, Oscillator::initial());
  fresh->start(osc, 0.0, Oscillator::initial());
  for (int k = 1; k <= 50; ++k) {
    const double t_end = 0.2 * k;
    ASSERT_EQ(run_to(*smooth, t_end).status, StepStatus::ok);
    ASSERT_EQ(run_to(*fresh, t_end).status, StepStatus::ok);
    const Vec ys = smooth->y(), yf = fresh->y();
    smooth->continue_smoothly(osc, t_end, ys);
    fresh->start(osc, t_end, yf);
  }
  EXPECT_LT((smooth->y() - Oscillator::exact(10.0)).norm(), 1e-7);
  if (GetParam() == Method::radau5)
    EXPECT_EQ(smooth->stats().rhs_evals, fresh->stats().rhs_evals);
  else
    EXPECT_LE(smooth->stats().rhs_evals, fresh->stats().rhs_evals - 50);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, IntegratorsRestart, ::testing::ValuesIn(all_methods()),
                         [](const auto& info) { return std::string(method_name(info.param)); });

}  // namespace
}  // namespace vibro::testing
