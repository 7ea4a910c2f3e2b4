// The checks of one plot spec that need no drawing code: its pellets against the model, its
// branches, window and instant against the run, its axis ranges and its camera. The scene reader
// runs them on every plot it reads (io/scene.h, validate_scene) and the figure's check before
// drawing (render/figure.h, validate_figure): one set of checks for a spec read from JSON and
// one built in code. Compiled without cairo (vibro_plot_spec), so that the scene reader links it.
#pragma once

#include <limits>
#include <optional>
#include <string>

#include "core/run/limits.h"
#include "core/run/validate.h"
#include "render/plot_spec.h"

namespace vibro {

// What a plot is checked against: the model's pellets and the run's end, s (infinite when the
// run is not known yet; the run's end is then checked when the plot is drawn).
struct PlotContext {
  int pellets = 0;
  double t_end = std::numeric_limits<double>::infinity();
};

// The plot at `field` ("plots[2]"); its errors name "plots[2].pellet" and so on. The 3-D panel's
// format and availability are the figure's to check (validate_figure).
std::optional<FieldError> validate_plot(const PlotSpec& plot, const std::string& field,
                                        const PlotContext& context, const Limits& limits);

}  // namespace vibro
