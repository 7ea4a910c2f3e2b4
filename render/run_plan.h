// What a figure needs from a run, so a scene computes only what its plots draw: branches kept
// only for the pellets drawn, the simulation stopped at the end of the latest window drawn, and
// no trust check (its fields are not drawn).
#pragma once

#include <vector>

#include "core/run/sim_options.h"
#include "render/plot_spec.h"

namespace vibro {

struct RunPlan {
  SimOptions options;  // the base options with record flags, record_until and t_end set
  bool needs_3d = false;
  bool needs_work_precision = false;  // a work-precision sweep of the scene
};

RunPlan plan_run(const FigureSpec& figure, const SimOptions& base, int pellets);

}  // namespace vibro
