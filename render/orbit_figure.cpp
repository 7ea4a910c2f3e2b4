#include "render/orbit_figure.h"

namespace vibro {

bool draws_branch(const OrbitFigure& in) {
  return in.branch && in.continuation && !in.branch->points.empty();
}

bool sweep_of_curves(const SweepSpec& sweep, const ContinuationSpec& continuation,
                     const FollowSpec& follow) {
  if (!sweep.axis2) return false;
  const std::string &a = sweep.axis.parameter, &b = sweep.axis2->parameter;
  return (a == continuation.parameter && b == follow.parameter2) ||
         (b == continuation.parameter && a == follow.parameter2);
}

RenderResult render_branch_figure(const FigureSpec& figure, const Model& model,
                                  const OrbitFigure& in, ImageFormat format) {
  if (in.curves && in.follow && !in.curves->empty()) {
    FigureSpec curves = figure;
    BranchPlot plot;
    plot.curves = true;
    curves.plots = {plot};
    PanelData data{nullptr, std::nullopt,
                   BranchData{*in.branch, *in.continuation, in.curves, in.follow}};
    if (in.sweep && in.sweep_spec && sweep_of_curves(*in.sweep_spec, *in.continuation, *in.follow))
      data.sweep.emplace(SweepData{*in.sweep_spec, *in.sweep});
    return render_figure(curves, model, RunResult{}, format, data);
  }
  FigureSpec branch = figure;
  branch.plots = {BranchPlot{}};
  const bool beneath = in.sweep && in.sweep_spec && !in.sweep_spec->axis2 &&
                       in.sweep_spec->axis.parameter == in.continuation->parameter;
  PanelData data{nullptr, std::nullopt, BranchData{*in.branch, *in.continuation}};
  if (beneath) data.sweep.emplace(SweepData{*in.sweep_spec, *in.sweep});
  return render_figure(branch, model, RunResult{}, format, data);
}

}  // namespace vibro
