// Checks of a figure request that can be made before any simulation.
#include <cmath>

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

std::optional<FieldError> check_plot(std::size_t i, const PlotSpec& plot, const Model& model,
                                     ImageFormat format) {
  if (plot.kind == PlotKind::time) {
    if (plot.pellets.empty() && model.size() == 0)
      return FieldError{plot_field(i, "pellets"), "the model has no pellets"};
    for (std::size_t j = 0; j < plot.pellets.size(); ++j) {
      const std::string field = plot_field(i, "pellets") + "[" + std::to_string(j) + "]";
      if (auto e = check_pellet(field, plot.pellets[j], model.size())) return e;
    }
  } else if (plot.kind == PlotKind::work_precision || plot.kind == PlotKind::mechanism) {
    // Draws the work-precision sweep, or every pellet: no pellet to check.
  } else if (auto e = check_pellet(plot_field(i, "pellet"), plot.pellet, model.size())) {
    return e;
  }
  for (std::size_t j = 0; j < plot.branches.size(); ++j)
    if (plot.branches[j] < 1)
      return FieldError{plot_field(i, "branches") + "[" + std::to_string(j) + "]",
                        "must be a branch number ≥ 1 (branches count from 1)"};
  if (!std::isfinite(plot.t_from) || plot.t_from < 0.0)
    return FieldError{plot_field(i, "t_from"), "must be a finite time ≥ 0 s"};
  if (std::isnan(plot.t_to) || plot.t_to <= plot.t_from)
    return FieldError{plot_field(i, "t_to"), "must be later than t_from"};
  // Whether t is within the run is checked against the run (render_figure).
  if (plot.kind == PlotKind::mechanism && !(std::isfinite(plot.t) && plot.t >= 0.0))
    return FieldError{plot_field(i, "t"), "must be a finite time ≥ 0 s, within [0, t_end]"};
  if (plot.first_integral_through && (!std::isfinite(plot.first_integral_through->phi) ||
                                      !std::isfinite(plot.first_integral_through->dphi)))
    return FieldError{plot_field(i, "first_integral_through"), "must be a finite (phi, dphi)"};
  if (plot.kind == PlotKind::cylinder) {
    if (format != ImageFormat::png)
      return FieldError{plot_field(i, "kind"), "3-D panels render only to PNG"};
    if (!cylinder_panels_available())
      return FieldError{plot_field(i, "kind"), "3-D panels are not available in this build"};
    const Camera& c = plot.camera;
    if (!std::isfinite(c.azimuth_deg) || !std::isfinite(c.elevation_deg) ||
        !std::isfinite(c.distance) || c.distance <= 0.0)
      return FieldError{plot_field(i, "camera"),
                        "needs finite angles (degrees) and a distance > 0"};
  }
  return std::nullopt;
}

}  // namespace

std::optional<FieldError> validate_sweep_plot(PlotKind kind, const SweepSpec& spec) {
  if (kind != PlotKind::lyapunov && kind != PlotKind::lyapunov_map) return std::nullopt;
  const std::string name = kind == PlotKind::lyapunov ? "\"lyapunov\"" : "\"lyapunov_map\"";
  if (!spec.lyapunov)
    return FieldError{"sweep.lyapunov", "must be true for the " + name +
                                            " plot: this sweep computed no Lyapunov exponents"};
  if (kind == PlotKind::lyapunov && spec.axis2)
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
    if (auto e = check_plot(i, figure.plots[i], model, format)) return e;
  return std::nullopt;
}

}  // namespace vibro
