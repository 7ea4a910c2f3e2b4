// Failure modes and the step contract: NaN, finite-time blow-up, singular Newton matrices,
// t_limit and h_max.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/integrators/radau5.h"
#include "core/integrators/stepper.h"
#include "tests/integrators/test_problems.h"

namespace vibro::testing {
namespace {

class IntegratorsFailure : public ::testing::TestWithParam<Method> {};

TEST_P(IntegratorsFailure, NanFromTheStartIsNonFinite) {
  const NanAfter sys(-1.0);
  auto s = make_stepper(GetParam(), StepperOptions{});
  s->start(sys, 0.0, Vec::Ones(1));
  EXPECT_EQ(s->step(1.0), StepStatus::non_finite);
  EXPECT_EQ(s->t(), 0.0);
  EXPECT_EQ(s->y()[0], 1.0);
}

TEST_P(IntegratorsFailure, NanLaterIsNonFiniteAndKeepsTheLastAcceptedPoint) {
  const NanAfter sys(0.5);
  StepperOptions o;
  o.rtol = 1e-6;
  auto s = make_stepper(GetParam(), o);
  s->start(sys, 0.0, Vec::Ones(1));
  double t_last = 0.0;
  double y_last = 1.0;
  StepStatus status = StepStatus::ok;
  for (int i = 0; i < 10'000 && status == StepStatus::ok; ++i) {
    status = s->step(2.0);
    if (status == StepStatus::ok) {
      t_last = s->t();
      y_last = s->y()[0];
    }
  }
  EXPECT_EQ(status, StepStatus::non_finite);
  EXPECT_EQ(s->t(), t_last);
  EXPECT_EQ(s->y()[0], y_last);
  EXPECT_LE(t_last, 0.5);
  EXPECT_NEAR(y_last, std::exp(-t_last), 1e-5);
}

TEST_P(IntegratorsFailure, BlowUpEndsInUnderflowOrNonFinite) {
  const BlowUp sys;
  StepperOptions o;
  o.rtol = 1e-8;
  o.atol = 1e-8;
  auto s = make_stepper(GetParam(), o);
  s->start(sys, 0.0, Vec::Ones(1));
  const RunResult run = run_to(*s, 2.0, 100'000);
  EXPECT_TRUE(run.status == StepStatus::step_underflow || run.status == StepStatus::non_finite)
      << "status " << static_cast<int>(run.status) << " after " << run.steps << " steps";
  EXPECT_LT(run.steps, 100'000);
  // The numerical solution blows up within round-off and tolerance of t = 1.
  EXPECT_NEAR(s->t(), 1.0, 1e-3);
  EXPECT_TRUE(std::isfinite(s->y()[0]));
}

TEST_P(IntegratorsFailure, RestartAfterAFailureIsNotStuckWithATinyStep) {
  const BlowUp blow_up;
  const Oscillator sys;
  StepperOptions o;
  o.rtol = 1e-8;
  auto s = make_stepper(GetParam(), o);
  s->start(blow_up, 0.0, Vec::Ones(1));
  ASSERT_NE(run_to(*s, 2.0, 100'000).status, StepStatus::ok);
  s->start(sys, 0.0, Oscillator::initial());
  ASSERT_EQ(s->step(10.0), StepStatus::ok);
  // The first step is HINIT's guess, as for a fresh stepper, not the blow-up's last step size.
  auto fresh = make_stepper(GetParam(), o);
  fresh->start(sys, 0.0, Oscillator::initial());
  ASSERT_EQ(fresh->step(10.0), StepStatus::ok);
  EXPECT_EQ(s->t(), fresh->t());
  ASSERT_EQ(run_to(*s, 10.0).status, StepStatus::ok);
  EXPECT_LT((s->y() - Oscillator::exact(10.0)).norm(), 1e-6);
}

TEST_P(IntegratorsFailure, StepsLandExactlyOnTLimitAndRespectHMax) {
  const Oscillator sys;
  StepperOptions o;
  o.rtol = 1e-6;
  o.h_max = 0.3;
  auto s = make_stepper(GetParam(), o);
  s->start(sys, 0.0, Oscillator::initial());
  for (double t_limit : {0.1, 0.1000001, 1.0, 1.37, 5.0}) {
    while (s->t() < t_limit) {
      ASSERT_EQ(s->step(t_limit), StepStatus::ok);
      EXPECT_LE(s->t(), t_limit);
      EXPECT_LE(s->t() - s->t_prev(), o.h_max * (1.0 + 1e-14));  // round-off of t_prev + h
      EXPECT_GT(s->t() - s->t_prev(), 0.0);
    }
    EXPECT_EQ(s->t(), t_limit);
  }
  EXPECT_LT((s->y() - Oscillator::exact(5.0)).norm(), 1e-4);
}

TEST_P(IntegratorsFailure, NoSliverStepBeforeTLimit) {
  const Oscillator sys;
  StepperOptions o;
  o.rtol = 1e-6;
  for (double t_end = 5.0; t_end < 6.0; t_end += 0.0123) {
    auto s = make_stepper(GetParam(), o);
    s->start(sys, 0.0, Oscillator::initial());
    double h_before_last = 0.0;
    double h_last = 0.0;
    const RunResult run = run_to(*s, t_end, 1'000'000, [&](const Stepper& st) {
      h_before_last = h_last;
      h_last = st.t() - st.t_prev();
    });
    ASSERT_EQ(run.status, StepStatus::ok);
    // The rest before t_end is split evenly rather than leaving a sliver.
    EXPECT_GT(h_last, 0.3 * h_before_last) << "t_end " << t_end;
  }
}

INSTANTIATE_TEST_SUITE_P(AllMethods, IntegratorsFailure, ::testing::ValuesIn(all_methods()),
                         [](const auto& info) { return std::string(method_name(info.param)); });

// A Jacobian of NaNs makes every Newton matrix "singular": RADAU5 gives up.
class NanJacobian final : public OdeSystem {
 public:
  int dimension() const override { return 1; }
  void rhs(double, const Vec& y, Vec& dydt) const override { dydt[0] = -y[0]; }
  void jacobian(double, const Vec&, Mat& dfdy, Vec& dfdt) const override {
    dfdy(0, 0) = std::numeric_limits<double>::quiet_NaN();
    dfdt.setZero();
  }
};

TEST(IntegratorsRadau5Failure, SingularMatrixIsSolverFailure) {
  const NanJacobian sys;
  integrators::Radau5 s(StepperOptions{});
  s.start(sys, 0.0, Vec::Ones(1));
  EXPECT_EQ(s.step(1.0), StepStatus::solver_failure);
  EXPECT_EQ(s.t(), 0.0);
}

// A wrong (sign-flipped) Jacobian on a stiff problem: Newton diverges at large steps, RADAU5
// shrinks the step instead of failing or returning garbage.
class WrongJacobian final : public OdeSystem {
 public:
  int dimension() const override { return 1; }
  void rhs(double, const Vec& y, Vec& dydt) const override { dydt[0] = -50.0 * y[0]; }
  void jacobian(double, const Vec&, Mat& dfdy, Vec& dfdt) const override {
    dfdy(0, 0) = 0.0;
    dfdt.setZero();
  }
};

TEST(IntegratorsRadau5Failure, NewtonFailureReducesTheStep) {
  const WrongJacobian sys;
  StepperOptions o;
  o.rtol = 1e-8;
  integrators::Radau5 s(o);
  s.start(sys, 0.0, Vec::Ones(1));
  const RunResult run = run_to(s, 0.5);
  ASSERT_EQ(run.status, StepStatus::ok);
  EXPECT_NEAR(s.y()[0], std::exp(-25.0), 1e-9);
}

}  // namespace
}  // namespace vibro::testing
