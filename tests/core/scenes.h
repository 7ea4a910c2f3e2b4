// Small scenes built in code for the physics tests, and helpers to read runs.
#pragma once

#include <string>
#include <vector>

#include "core/model/model.h"
#include "core/run/result.h"
#include "core/run/sim_options.h"
#include "io/scene.h"

namespace vibro::testing {

// A one-pellet model on R = 0.5 m, g = 9.81.
Model one_pellet(double alpha0, double phi0, double dphi0);
// A preset by name, parsed; fails the test if it does not parse.
Scene preset(const std::string& name);
// Options for t_end with every pellet recorded.
SimOptions recorded(const Model& model, double t_end, Method method = Method::automatic,
                    double rtol = 1e-10, double atol = 1e-12);
// "dop853 at rtol 1e-10", for messages.
std::string method_at(Method method, double rtol);
std::vector<const Event*> events_of(const RunResult& run, EventKind kind);
bool all_finite(const RunResult& run);

}  // namespace vibro::testing
