// Checks of a figure request that can be made before any simulation.
#include <cmath>
#include <variant>

#include "render/figure.h"

namespace vibro {
namespace {

std::string plot_field(std::size_t i, const char* name) {
  return "plots[" + std::to_string(i) + "]." + name;
}

std::optional<FieldError> check_pellet(const std::string& field, int pellet, int count) {
  if (pellet >= 0 && pellet < count) return std::nullopt;
  if (count == 0) return FieldError{field, "the model has no pellets"};
  return FieldError{field, "must be a pellet index in 0.." + std::to_string(count - 1) +
                               " (indices count from 0: pellet 1 is 0), got " +
                               std::to_string(pellet)};
}

std::optional<FieldError> check_window(std::size_t i, const TimeWindow& w) {
  if (!std::isfinite(w.t_from) || w.t_from < 0.0)
    return FieldError{plot_field(i, "t_from"), "must be a finite time ≥ 0 s"};
  if (std::isnan(w.t_to) || w.t_to <= w.t_from)
    return FieldError{plot_field(i, "t_to"), "must be later than t_from"};
  return std::nullopt;
}

// Each kind's checks, in the order a plot's fields are reported: its pellets, its branches, its
// window, its instant, its overlay, its 3-D view.
struct PlotCheck {
  std::size_t i;
  const Model& model;
  ImageFormat format;

  using Checked = std::optional<FieldError>;

  Checked pellet(int p) const { return check_pellet(plot_field(i, "pellet"), p, model.size()); }
  Checked operator()(const PhasePlot& plot) const {
    if (auto e = pellet(plot.pellet)) return e;
    for (std::size_t j = 0; j < plot.branches.size(); ++j)
      if (plot.branches[j] < 1)
        return FieldError{plot_field(i, "branches") + "[" + std::to_string(j) + "]",
                          "must be a branch number ≥ 1 (branches count from 1)"};
    if (auto e = check_window(i, plot)) return e;
    const auto& through = plot.first_integral_through;
    if (through && (!std::isfinite(through->phi) || !std::isfinite(through->dphi)))
      return FieldError{plot_field(i, "first_integral_through"), "must be a finite (phi, dphi)"};
    return std::nullopt;
  }
  Checked operator()(const TimePlot& plot) const {
    if (plot.pellets.empty() && model.size() == 0)
      return FieldError{plot_field(i, "pellets"), "the model has no pellets"};
    for (std::size_t j = 0; j < plot.pellets.size(); ++j) {
      const std::string field = plot_field(i, "pellets") + "[" + std::to_string(j) + "]";
      if (auto e = check_pellet(field, plot.pellets[j], model.size())) return e;
    }
    return check_window(i, plot);
  }
  Checked operator()(const CylinderPlot& plot) const {
    if (auto e = pellet(plot.pellet)) return e;
    if (auto e = check_window(i, plot)) return e;
    if (format != ImageFormat::png)
      return FieldError{plot_field(i, "kind"), "3-D panels render only to PNG"};
    if (!cylinder_panels_available())
      return FieldError{plot_field(i, "kind"), "3-D panels are not available in this build"};
    const Camera& c = plot.camera;
    if (!std::isfinite(c.azimuth_deg) || !std::isfinite(c.elevation_deg) ||
        !std::isfinite(c.distance) || c.distance <= 0.0)
      return FieldError{plot_field(i, "camera"),
                        "needs finite angles (degrees) and a distance > 0"};
    return std::nullopt;
  }
  // Every pellet, at one instant; whether t is within the run is checked against the run
  // (render_figure).
  Checked operator()(const MechanismPlot& plot) const {
    if (!(std::isfinite(plot.t) && plot.t >= 0.0))
      return FieldError{plot_field(i, "t"), "must be a finite time ≥ 0 s, within [0, t_end]"};
    return std::nullopt;
  }
  // Draws the work-precision sweep: no pellet to check.
  Checked operator()(const WorkPrecisionPlot& plot) const { return check_window(i, plot); }
  Checked operator()(const SweepPlot& plot) const { return pellet(plot.pellet); }
  Checked operator()(const BranchPlot& plot) const { return pellet(plot.pellet); }
};

}  // namespace

std::optional<FieldError> validate_sweep_plot(SweepView view, const SweepSpec& spec) {
  if (view != SweepView::lyapunov && view != SweepView::lyapunov_map) return std::nullopt;
  const std::string name = view == SweepView::lyapunov ? "\"lyapunov\"" : "\"lyapunov_map\"";
  if (!spec.lyapunov)
    return FieldError{"sweep.lyapunov", "must be true for the " + name +
                                            " plot: this sweep computed no Lyapunov exponents"};
  if (view == SweepView::lyapunov && spec.axis2)
    return FieldError{"sweep.parameter2",
                      "makes a 2-D sweep, which the \"lyapunov\" plot (one "
                      "parameter) cannot draw: draw it as \"lyapunov_map\""};
  return std::nullopt;
}

std::optional<FieldError> validate_figure(const FigureSpec& figure, const Model& model,
                                          ImageFormat format, const Limits& limits) {
  if (auto e = check_figure_size(figure, limits)) return e;
  if (figure.plots.empty()) return FieldError{"plots", "must list at least one plot"};
  if (static_cast<int>(figure.plots.size()) > limits.plots)
    return FieldError{"plots", "must list at most " + std::to_string(limits.plots) + " plots"};
  for (std::size_t i = 0; i < figure.plots.size(); ++i)
    if (auto e = std::visit(PlotCheck{i, model, format}, figure.plots[i])) return e;
  return std::nullopt;
}

}  // namespace vibro
