// A scene: the model, the run, and the plots, as a request names them (API.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/analysis/sweep.h"
#include "core/model/model.h"
#include "core/run/limits.h"
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

// Why the scene cannot run, naming the field: each of its parts checked against `limits`, in
// this order: the figure's sides (render/figure_size.h), the model, the run's options, the sweep
// and the periodic-orbit request. The figure's pixels and plots are checked when it is drawn
// (render/figure.h, validate_figure): a scene that is only simulated needs no image.
std::optional<FieldError> validate_scene(const Scene& scene, const Limits& limits = {});

}  // namespace vibro
