#include "render/run_plan.h"

#include <algorithm>
#include <limits>
#include <type_traits>
#include <variant>

#include "render/track_window.h"

namespace vibro {
namespace {

// How far into the run a plot draws: the end of its window; a mechanism shows one instant, and
// the run need go no further; a sweep or a branch draws none of it, and sets no end.
double run_until(const PlotSpec& plot) {
  if (const auto* mechanism = std::get_if<MechanismPlot>(&plot)) return mechanism->t;
  return std::visit(
      [](const auto& p) {
        if constexpr (std::is_base_of_v<TimeWindow, std::decay_t<decltype(p)>>) return p.t_to;
        return std::numeric_limits<double>::infinity();
      },
      plot);
}

}  // namespace

RunPlan plan_run(const FigureSpec& figure, const SimOptions& base, int pellets) {
  RunPlan plan;
  plan.options = base;
  plan.options.record.assign(pellets, false);
  // The trust check's fields are answered by a run's JSON; nothing drawn reads them yet.
  plan.options.check = false;
  plan.options.lyapunov = false;
  double until = 0.0;
  for (const PlotSpec& p : figure.plots) {
    plan.needs_work_precision =
        plan.needs_work_precision || std::holds_alternative<WorkPrecisionPlot>(p);
    // Only the pellets drawn; a sweep, a report or a branch draws none of the run.
    for (int i : render::panel_pellets(p, pellets))
      if (i >= 0 && i < pellets) plan.options.record[i] = true;
    plan.needs_3d = plan.needs_3d || std::holds_alternative<CylinderPlot>(p);
    until = std::max(until, run_until(p));
  }
  if (!figure.plots.empty()) {
    plan.options.t_end = std::min(base.t_end, until);
    plan.options.record_until = plan.options.t_end;
  }
  return plan;
}

}  // namespace vibro
