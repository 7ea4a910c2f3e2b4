// No heap allocation in step() or dense(), nor in a restart at the same dimension.
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>
#include <string>

#include "core/integrators/stepper.h"
#include "tests/integrators/test_problems.h"

namespace {
long g_allocations = 0;
}  // namespace

// Counts every allocation of this test program. (GCC cannot see that the replaced operator new
// uses malloc, hence the pragma.)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace vibro::testing {
namespace {

class IntegratorsAllocation : public ::testing::TestWithParam<Method> {};

TEST_P(IntegratorsAllocation, StepDenseAndRestartDoNotAllocate) {
  // Van der Pol with a moderate mu: non-stiff at first, stiff later, so "auto" switches too.
  const VanDerPol sys(1e-3);
  StepperOptions o;
  o.rtol = 1e-7;
  auto s = make_stepper(GetParam(), o);
  Vec out(2);
  Vec y0 = VanDerPol::initial();
  s->start(sys, 0.0, y0);
  ASSERT_EQ(s->step(3.0), StepStatus::ok);

  const long before = g_allocations;
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 200 && s->t() < 3.0; ++i) {
      ASSERT_EQ(s->step(3.0), StepStatus::ok);
      s->dense(0.5 * (s->t_prev() + s->t()), out);
    }
    y0 = s->y();
    s->start(sys, s->t(), y0);
  }
  EXPECT_EQ(g_allocations - before, 0);
}

// 12 coupled oscillators (n = 24): above 16 unknowns Eigen factorises in blocks.
class Chain final : public OdeSystem {
 public:
  int dimension() const override { return 24; }
  void rhs(double, const Vec& y, Vec& dydt) const override {
    for (int i = 0; i < 12; ++i) {
      const double left = i > 0 ? y[2 * i - 2] : 0.0;
      const double right = i < 11 ? y[2 * i + 2] : 0.0;
      dydt[2 * i] = y[2 * i + 1];
      dydt[2 * i + 1] = left - 2.0 * y[2 * i] + right;
    }
  }
  void jacobian(double, const Vec&, Mat& dfdy, Vec& dfdt) const override {
    dfdy.setZero();
    for (int i = 0; i < 12; ++i) {
      dfdy(2 * i, 2 * i + 1) = 1.0;
      dfdy(2 * i + 1, 2 * i) = -2.0;
      if (i > 0) dfdy(2 * i + 1, 2 * i - 2) = 1.0;
      if (i < 11) dfdy(2 * i + 1, 2 * i + 2) = 1.0;
    }
    dfdt.setZero();
  }
};

TEST_P(IntegratorsAllocation, LargestTypicalDimensionDoesNotAllocate) {
  const Chain sys;
  StepperOptions o;
  o.rtol = 1e-8;
  auto s = make_stepper(GetParam(), o);
  Vec out(24);
  const Vec y0 = Vec::LinSpaced(24, -1.0, 1.0);
  s->start(sys, 0.0, y0);
  ASSERT_EQ(s->step(50.0), StepStatus::ok);
  const long before = g_allocations;
  for (int i = 0; i < 100; ++i) {
    ASSERT_EQ(s->step(50.0), StepStatus::ok);
    s->dense(0.5 * (s->t_prev() + s->t()), out);
  }
  s->start(sys, s->t(), out);
  ASSERT_EQ(s->step(50.0), StepStatus::ok);
  EXPECT_EQ(g_allocations - before, 0);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, IntegratorsAllocation, ::testing::ValuesIn(all_methods()),
                         [](const auto& info) { return std::string(method_name(info.param)); });

}  // namespace
}  // namespace vibro::testing
