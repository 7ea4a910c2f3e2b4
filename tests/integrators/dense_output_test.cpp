// Dense output: accuracy inside the steps, agreement with the step ends, and its order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/integrators/stepper.h"
#include "tests/integrators/test_problems.h"

namespace vibro::testing {
namespace {

// Largest error of dense output at 9 interior points of every step of a run to t_end.
template <class Problem>
double max_dense_error(Stepper& s, double t_end) {
  const Problem sys;
  s.start(sys, 0.0, Problem::initial());
  double worst = 0.0;
  Vec out(sys.dimension());
  const RunResult run = run_to(s, t_end, 1'000'000, [&](const Stepper& st) {
    for (int j = 1; j <= 9; ++j) {
      const double t = st.t_prev() + (st.t() - st.t_prev()) * j / 10.0;
      st.dense(t, out);
      worst = std::max(worst, (out - Problem::exact(t)).cwiseAbs().maxCoeff());
    }
  });
  EXPECT_EQ(run.status, StepStatus::ok);
  return worst;
}

class IntegratorsDense : public ::testing::TestWithParam<Method> {};

TEST_P(IntegratorsDense, InterpolantIsAsAccurateAsTheTolerance) {
  for (double rtol : {1e-6, 1e-9}) {
    StepperOptions o;
    o.rtol = rtol;
    o.atol = rtol;
    auto s = make_stepper(GetParam(), o);
    const double e_osc = max_dense_error<Oscillator>(*s, 10.0);
    const double e_gauss = max_dense_error<Gaussian>(*s, 3.0);
    SCOPED_TRACE("rtol " + std::to_string(rtol));
    // Within two orders of magnitude of rtol, like the solution at the step points (DOP853 at
    // loose tolerances and RADAU5's stage-order-3 interpolant are the worst).
    EXPECT_LT(e_osc, 100.0 * rtol);
    EXPECT_LT(e_gauss, 100.0 * rtol);
    EXPECT_GT(s->stats().steps, 20);  // the interpolant was really used inside steps
  }
}

TEST_P(IntegratorsDense, InterpolantMeetsTheStepEnds) {
  const Oscillator sys;
  StepperOptions o;
  o.rtol = 1e-7;
  auto s = make_stepper(GetParam(), o);
  s->start(sys, 0.0, Oscillator::initial());
  Vec prev = Oscillator::initial();
  Vec out(2);
  run_to(*s, 5.0, 1'000'000, [&](const Stepper& st) {
    st.dense(st.t_prev(), out);
    EXPECT_LT((out - prev).norm(), 1e-13);
    st.dense(st.t(), out);
    EXPECT_LT((out - st.y()).norm(), 1e-13);
    prev = st.y();
  });
}

// The interpolant leaves each step's start with the right-hand side's slope: the event core
// watches a quantity that starts on its root through (g(t) − g(t0))/(t − t0), which near t0 reads
// that slope. RADAU5's collocation polynomial alone errs there by O(h³) (a pellet starting at
// equilibrium was seen to turn back every 8e-16 s); loose tolerances make the steps long.
TEST_P(IntegratorsDense, InterpolantStartsWithTheRightHandSidesSlope) {
  const Gaussian sys;
  StepperOptions o;
  o.rtol = 1e-3;
  o.atol = 1e-3;
  auto s = make_stepper(GetParam(), o);
  s->start(sys, 0.0, Gaussian::initial());
  Vec a(1), b(1), f(1);
  int checked = 0;
  run_to(*s, 3.0, 1'000'000, [&](const Stepper& st) {
    const double h = st.t() - st.t_prev();
    const double delta = 1e-6 * h;
    st.dense(st.t_prev(), a);
    st.dense(st.t_prev() + delta, b);
    sys.rhs(st.t_prev(), a, f);
    const double slope = (b[0] - a[0]) / delta;
    // The difference quotient errs by y''·delta/2, below 1e-6·h here.
    EXPECT_NEAR(slope, f[0], 1e-5 * (1.0 + std::abs(f[0]))) << "step from t = " << st.t_prev();
    ++checked;
  });
  EXPECT_GT(checked, 5);
}

// precise_state: the state inside a step as accurate as a step's end, where events are
// placed. Every method's interpolant is of lower order than its steps. Measured from each
// step's own start (the exact rotation of the oscillator's state there) at rtol 1e-6, the
// local error of precise_state inside a step stays below that of the step's end; the
// interpolant's is 8 (DOPRI5), 41 (DOP853) and 200 (Radau IIA) times larger: DOP853's errs 16
// times a step's end.
TEST_P(IntegratorsDense, PreciseStateIsAsAccurateAsAStepsEnd) {
  const Oscillator sys;
  StepperOptions o;
  o.rtol = 1e-6;
  o.atol = 1e-6;
  auto s = make_stepper(GetParam(), o);
  s->start(sys, 0.0, Oscillator::initial());
  const auto from = [](const Vec& y0, double dt) {  // the exact flow over dt
    return Vec{
        {y0[0] * std::cos(dt) + y0[1] * std::sin(dt), y0[1] * std::cos(dt) - y0[0] * std::sin(dt)}};
  };
  double end_worst = 0.0, dense_worst = 0.0, precise_worst = 0.0;
  Vec start(2), out(2);
  while (s->t() < 10.0) {
    ASSERT_EQ(s->step(10.0), StepStatus::ok);
    const double a = s->t_prev(), h = s->t() - a;
    s->dense(a, start);
    end_worst = std::max(end_worst, (s->y() - from(start, h)).cwiseAbs().maxCoeff());
    for (int j = 1; j <= 9; ++j) {
      const double t = a + h * j / 10.0;
      s->dense(t, out);
      dense_worst = std::max(dense_worst, (out - from(start, t - a)).cwiseAbs().maxCoeff());
      s->precise_state(t, out);
      precise_worst = std::max(precise_worst, (out - from(start, t - a)).cwiseAbs().maxCoeff());
    }
  }
  EXPECT_LT(precise_worst, end_worst);
  EXPECT_GT(dense_worst, 3.0 * precise_worst);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, IntegratorsDense, ::testing::ValuesIn(all_methods()),
                         [](const auto& info) {
                           const std::string_view n = method_name(info.param);
                           return std::string(n);
                         });

// With fixed steps the midpoint error of the interpolant falls like h^q: q = 5 for DOPRI5's
// 4th-order dense output, 8 for DOP853's 7th-order one, and 4 for RADAU5's collocation
// polynomial (stage order 3).
double midpoint_error(Method method, double h) {
  const Oscillator sys;
  auto s = make_stepper(method, fixed_step(h));
  s->start(sys, 0.0, Oscillator::initial());
  double worst = 0.0;
  Vec out(2);
  run_to(*s, 4.0, 1'000'000, [&](const Stepper& st) {
    const double t = 0.5 * (st.t_prev() + st.t());
    st.dense(t, out);
    worst = std::max(worst, (out - Oscillator::exact(t)).norm());
  });
  return worst;
}

TEST(IntegratorsDenseOrder, InterpolantsHaveTheirDesignOrder) {
  const struct {
    Method method;
    double h;
    double order;
  } cases[] = {{Method::dopri5, 0.2, 5.0}, {Method::dop853, 0.8, 8.0}, {Method::radau5, 0.2, 4.0}};
  for (const auto& c : cases) {
    const double e1 = midpoint_error(c.method, c.h);
    const double e2 = midpoint_error(c.method, c.h / 2);
    SCOPED_TRACE(std::string(method_name(c.method)));
    EXPECT_NEAR(std::log2(e1 / e2), c.order, 0.6);
  }
}

}  // namespace
}  // namespace vibro::testing
