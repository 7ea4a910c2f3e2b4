#include "render/run_plan.h"

#include <algorithm>

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
    if (p.kind == PlotKind::work_precision) {
      plan.needs_work_precision = true;
    } else if (!draws_run(p.kind)) {
      // Draws a sweep or a branch: nothing from the run.
    } else if (p.kind == PlotKind::time) {
      if (p.pellets.empty()) plan.options.record.assign(pellets, true);
      for (int i : p.pellets)
        if (i >= 0 && i < pellets) plan.options.record[i] = true;
    } else if (p.pellet >= 0 && p.pellet < pellets) {
      plan.options.record[p.pellet] = true;
    }
    plan.needs_3d = plan.needs_3d || p.kind == PlotKind::cylinder;
    until = std::max(until, p.t_to);
  }
  if (!figure.plots.empty()) {
    plan.options.t_end = std::min(base.t_end, until);
    plan.options.record_until = plan.options.t_end;
  }
  return plan;
}

}  // namespace vibro
