// Checks of a figure request that can be made before any simulation.
#include <cmath>
#include <variant>

#include "render/figure.h"
#include "render/plot_validate.h"

namespace vibro {
namespace {

std::string plot_field(std::size_t i) { return "plots[" + std::to_string(i) + "]"; }

// What only a drawing can tell: a 3-D panel needs PNG and a build with OSMesa.
std::optional<FieldError> check_drawable(std::size_t i, const PlotSpec& plot, ImageFormat format) {
  if (!std::holds_alternative<CylinderPlot>(plot)) return std::nullopt;
  if (format != ImageFormat::png)
    return FieldError{plot_field(i) + ".kind", "3-D panels render only to PNG"};
  if (!cylinder_panels_available())
    return FieldError{plot_field(i) + ".kind", "3-D panels are not available in this build"};
  return std::nullopt;
}

}  // namespace

std::optional<FieldError> validate_sweep_plot(SweepView view, const SweepSpec& spec) {
  if (view == SweepView::basins && !spec.classify_attractor)
    return FieldError{"sweep.classify",
                      "must be \"attractor\" for the \"basins\" plot: this sweep labelled no "
                      "run with an attractor"};
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
  for (std::size_t i = 0; i < figure.plots.size(); ++i) {
    if (auto e = validate_plot(figure.plots[i], plot_field(i), {model.size()}, limits)) return e;
    if (auto e = check_drawable(i, figure.plots[i], format)) return e;
  }
  return std::nullopt;
}

}  // namespace vibro
