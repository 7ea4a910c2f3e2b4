// No heap allocation in step() or dense(), nor in a restart at the same dimension.
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>
#include <string>

#include "core/stepper.h"
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

INSTANTIATE_TEST_SUITE_P(AllMethods, IntegratorsAllocation, ::testing::ValuesIn(all_methods()),
                         [](const auto& info) { return std::string(method_name(info.param)); });

}  // namespace
}  // namespace vibro::testing
