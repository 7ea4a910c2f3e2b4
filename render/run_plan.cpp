#include "render/run_plan.h"

#include <algorithm>

#include "render/track_window.h"

namespace vibro {

RunPlan plan_run(const FigureSpec& figure, const SimOptions& base, int pellets) {
  RunPlan plan;
  plan.options = base;
  plan.options.record.assign(pellets, false);
  // The trust check's fields are answered by a run's JSON; nothing drawn reads them yet.
  plan.options.check = false;
  plan.options.lyapunov = false;
  double until = 0.0;
  for (const PlotSpec& p : figure.plots) {
    plan.needs_work_precision = plan.needs_work_precision || p.kind == PlotKind::work_precision;
    // Only the pellets drawn; a sweep, a report or a branch draws none of the run.
    for (int i : render::panel_pellets(p, pellets))
      if (i >= 0 && i < pellets) plan.options.record[i] = true;
    plan.needs_3d = plan.needs_3d || p.kind == PlotKind::cylinder;
    // A mechanism shows one instant: the run need go no further.
    until = std::max(until, p.kind == PlotKind::mechanism ? p.t : p.t_to);
  }
  if (!figure.plots.empty()) {
    plan.options.t_end = std::min(base.t_end, until);
    plan.options.record_until = plan.options.t_end;
  }
  return plan;
}

}  // namespace vibro
