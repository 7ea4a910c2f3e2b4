// The paper scene of MODEL.md (δ₂ = π/2 and k = 0.4 assumed), for tests on a real run.
#pragma once

#include <numbers>

#include "core/model/model.h"
#include "core/run/sim_options.h"

namespace vibro::testing {

inline Model paper_model() {
  Model model;
  model.R = 0.5;
  model.alpha0 = 0.05;
  const double pi = std::numbers::pi;
  model.pellets = {Pellet{0.2, pi / 12, 50.0, Forcing{1.2, 3.3, 0.0}},
                   Pellet{0.2, -pi / 12, 6.0, {}}};
  model.limiters = {Limiter{pi / 4, 0.4, true, 1, {}}, Limiter{-pi / 2, 0.4, false, -1, {}}};
  model.k_c = 1.0;
  return model;
}

inline SimOptions paper_options() {
  SimOptions options;
  options.t_end = 12.0;
  options.record = {true, true};
  return options;
}

}  // namespace vibro::testing
