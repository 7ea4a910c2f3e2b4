#include "render/orbit_figure.h"

#include "core/analysis/checked_run.h"
#include "render/run_plan.h"

namespace vibro {

RenderResult render_orbit_figure(const FigureSpec& figure, const Model& model,
                                 const SimOptions& options, const OrbitFigure& in,
                                 ImageFormat format) {
  if (in.branch && in.continuation && !in.branch->points.empty()) {
    FigureSpec branch = figure;
    PlotSpec plot;
    plot.kind = PlotKind::branch;
    branch.plots = {plot};
    const bool beneath = in.sweep && in.sweep_spec && !in.sweep_spec->axis2 &&
                         in.sweep_spec->axis.parameter == in.continuation->parameter;
    return render_figure(branch, model, RunResult{}, format,
                         {nullptr, beneath ? in.sweep_spec : nullptr, beneath ? in.sweep : nullptr,
                          in.branch, in.continuation});
  }
  if (!in.orbit.converged)
    return {{},
            {},
            FieldError{"periodic_orbit", "no periodic motion to draw: " + in.orbit.message},
            {}};
  // One return from the orbit's state: its section time t0 is a whole number of every force's
  // periods, so the forces' phases are those of t = 0.
  Model on = model;
  for (int i = 0; i < on.size(); ++i) {
    on.pellets[i].phi0 = in.orbit.state[i].phi;
    on.pellets[i].dphi0 = in.orbit.state[i].dphi;
  }
  SimOptions once = options;
  once.t_end = in.orbit.periods * in.orbit.period;
  const RunPlan plan = plan_run(figure, once, on.size());
  return render_figure(figure, on, simulate(on, plan.options), format);
}

}  // namespace vibro
