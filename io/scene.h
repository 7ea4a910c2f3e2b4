// A scene: the model, the run, and the plots, as a request names them (API.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/analysis/sweep.h"
#include "core/model/model.h"
#include "core/run/sim_options.h"
#include "io/orbit_request.h"
#include "render/plot_spec.h"

namespace vibro {

struct Scene {
  std::string name;                      // presets only
  std::string description;               // what the scene shows, or what makes it hard
  std::vector<std::string> assumptions;  // values the source does not print
  Model model;
  SimOptions sim;             // t_end, method, tolerances
  bool trajectories = false;  // return the sampled branches with the run
  FigureSpec figure;
  std::optional<SweepSpec> sweep;  // run by `vibro sweep` and POST /api/sweep, not by simulate
  // Run by `vibro orbit` and POST /api/periodic-orbit, not by simulate; they take the defaults
  // when it is absent.
  std::optional<OrbitRequest> periodic_orbit;
};

// Bounds on what a scene may ask; the server tightens them.
struct SceneLimits {
  SimLimits sim;
  int max_plots = 8;
  int max_width = 4096;
  int max_height = 4096;
  int max_depth = 16;  // JSON nesting
};

}  // namespace vibro
