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

namespace {

bool draws_curves(const OrbitFigure& in) { return in.curves && in.follow && !in.curves->empty(); }

bool one_axis_of(const SweepSpec& sweep, const ContinuationSpec& continuation) {
  return !sweep.axis2 && sweep.axis.parameter == continuation.parameter;
}

}  // namespace

bool sweep_may_lie_beneath(const SweepSpec& sweep, const ContinuationSpec& continuation,
                           const FollowSpec* follow) {
  return one_axis_of(sweep, continuation) ||
         (follow && sweep_of_curves(sweep, continuation, *follow));
}

bool draws_sweep_beneath(const OrbitFigure& in) {
  if (!draws_branch(in) || !in.sweep_spec) return false;
  if (draws_curves(in)) return sweep_of_curves(*in.sweep_spec, *in.continuation, *in.follow);
  return one_axis_of(*in.sweep_spec, *in.continuation);
}

RenderResult render_branch_figure(const FigureSpec& figure, const Model& model,
                                  const OrbitFigure& in, ImageFormat format) {
  const bool beneath = in.sweep && draws_sweep_beneath(in);
  if (draws_curves(in)) {
    FigureSpec curves = figure;
    BranchPlot plot;
    plot.curves = true;
    curves.plots = {plot};
    PanelData data{nullptr, std::nullopt,
                   BranchData{*in.branch, *in.continuation, in.curves, in.follow}};
    if (beneath) data.sweep.emplace(SweepData{*in.sweep_spec, *in.sweep});
    return render_figure(curves, model, RunResult{}, format, data);
  }
  FigureSpec branch = figure;
  branch.plots = {BranchPlot{}};
  PanelData data{nullptr, std::nullopt, BranchData{*in.branch, *in.continuation}};
  if (beneath) data.sweep.emplace(SweepData{*in.sweep_spec, *in.sweep});
  return render_figure(branch, model, RunResult{}, format, data);
}

}  // namespace vibro
