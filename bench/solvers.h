// The integrators a work-precision comparison runs: vibro's methods, and the peers this build
// found (VIBRO_BENCH_ODEINT, VIBRO_BENCH_CVODE), each a factory of a Stepper for vibro's driver.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/integrators/stepper.h"

namespace vibro::bench {

struct Solver {
  std::string name;  // "dopri5", ..., "odeint-dopri5", "cvode-adams", "cvode-bdf"
  std::function<std::unique_ptr<Stepper>(const StepperOptions&)> make;
};

std::vector<Solver> solvers();

}  // namespace vibro::bench
