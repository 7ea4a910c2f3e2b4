// Order of convergence with fixed steps: halving h divides the global error by about 2^p.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/integrators/stepper.h"
#include "tests/integrators/test_problems.h"

namespace vibro::testing {
namespace {

// Largest global error at the step points of steps of size h over [t0, t_end] (the maximum over
// the trajectory, since the error at a single time may happen to cross zero). Tolerances are too
// loose to interfere, and the start points are chosen so that the initial step guess is at least
// h: every step is exactly h.
template <class Problem>
double global_error(Method method, double t0, double t_end, double h) {
  const Problem sys;
  auto s = make_stepper(method, fixed_step(h));
  s->start(sys, t0, Problem::exact(t0));
  double worst = 0.0;
  const RunResult run = run_to(*s, t_end, 1'000'000, [&](const Stepper& st) {
    worst = std::max(worst, (st.y() - Problem::exact(st.t())).norm());
  });
  EXPECT_EQ(run.status, StepStatus::ok);
  EXPECT_EQ(run.steps, std::lround((t_end - t0) / h));
  return worst;
}

template <class Problem>
void expect_order(Method method, double t0, double t_end, double h, double order,
                  double slack = 0.6) {
  const double e1 = global_error<Problem>(method, t0, t_end, h);
  const double e2 = global_error<Problem>(method, t0, t_end, h / 2);
  const double e3 = global_error<Problem>(method, t0, t_end, h / 4);
  const double p12 = std::log2(e1 / e2);
  const double p23 = std::log2(e2 / e3);
  std::ostringstream trace;
  trace << method_name(method) << " errors " << e1 << " " << e2 << " " << e3;
  SCOPED_TRACE(trace.str());
  EXPECT_NEAR(p12, order, slack);
  EXPECT_NEAR(p23, order, slack);
}

TEST(IntegratorsConvergence, Dopri5IsOrder5) {
  expect_order<Oscillator>(Method::dopri5, 0.0, 10.0, 0.2, 5.0);
  // DOPRI5's principal error term is small by design, so on this nonlinear problem the order
  // approaches 5 from above only slowly (5.7, 5.5 here).
  expect_order<LimitCycle>(Method::dopri5, 0.5, 5.5, 0.05, 5.0, 0.8);
  expect_order<Gaussian>(Method::dopri5, 0.5, 3.5, 0.1, 5.0);
}

TEST(IntegratorsConvergence, Dop853IsOrder8) {
  // Errors from 1e-7 down to 1e-12: smaller steps would reach round-off.
  expect_order<LimitCycle>(Method::dop853, 0.5, 5.5, 0.5, 8.0);
  expect_order<Gaussian>(Method::dop853, 0.5, 3.5, 0.25, 8.0);
}

// At the step points Radau IIA (3 stages) has the superconvergent order 2s − 1 = 5. (A linear
// autonomous problem, so that the loose Newton tolerance of the fixed-step setup is exact.)
TEST(IntegratorsConvergence, Radau5IsOrder5AtStepPoints) {
  expect_order<Oscillator>(Method::radau5, 1.0, 11.0, 0.25, 5.0);
}

}  // namespace
}  // namespace vibro::testing
