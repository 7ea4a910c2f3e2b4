// Tolerance proportionality: tighter rtol, smaller global error.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/integrators/stepper.h"
#include "tests/integrators/test_problems.h"

namespace vibro::testing {
namespace {

class IntegratorsTolerance : public ::testing::TestWithParam<Method> {};

TEST_P(IntegratorsTolerance, GlobalErrorFollowsTheTolerance) {
  const Oscillator sys;
  std::vector<double> errors;
  for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    StepperOptions o;
    o.rtol = rtol;
    o.atol = rtol;
    auto s = make_stepper(GetParam(), o);
    s->start(sys, 0.0, Oscillator::initial());
    ASSERT_EQ(run_to(*s, 10.0).status, StepStatus::ok);
    EXPECT_EQ(s->t(), 10.0);
    errors.push_back((s->y() - Oscillator::exact(10.0)).norm());
    // Not wildly off the requested accuracy in either direction.
    EXPECT_LT(errors.back(), 200.0 * rtol) << "rtol " << rtol;
  }
  for (size_t i = 1; i < errors.size(); ++i) {
    EXPECT_LT(errors[i], errors[i - 1] / 10.0) << "rtol step " << i;  // 100× tighter
  }
  EXPECT_LT(errors.back(), 1e-7);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, IntegratorsTolerance, ::testing::ValuesIn(all_methods()),
                         [](const auto& info) { return std::string(method_name(info.param)); });

}  // namespace
}  // namespace vibro::testing
