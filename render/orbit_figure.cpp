#include "render/orbit_figure.h"

namespace vibro {

bool draws_branch(const OrbitFigure& in) {
  return in.branch && in.continuation && !in.branch->points.empty();
}

RenderResult render_branch_figure(const FigureSpec& figure, const Model& model,
                                  const OrbitFigure& in, ImageFormat format) {
  FigureSpec branch = figure;
  branch.plots = {BranchPlot{}};
  const bool beneath = in.sweep && in.sweep_spec && !in.sweep_spec->axis2 &&
                       in.sweep_spec->axis.parameter == in.continuation->parameter;
  PanelData data{nullptr, std::nullopt, BranchData{*in.branch, *in.continuation}};
  if (beneath) data.sweep.emplace(SweepData{*in.sweep_spec, *in.sweep});
  return render_figure(branch, model, RunResult{}, format, data);
}

}  // namespace vibro
