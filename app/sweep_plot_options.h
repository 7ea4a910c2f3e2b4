// What `vibro sweep` and `vibro plot` draw a sweep as: --plot KIND, --pellet I, --coordinate C,
// checked against the scene's sweep; and the drawing of a sweep's result in the scene's figure
// size (and print size, when it has one).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "core/analysis/sweep.h"
#include "io/scene.h"
#include "render/figure.h"

namespace vibro {

struct SweepPlotOptions {
  std::string plot;                   // "" : the sweep's usual plot (io/sweep_json.h)
  std::optional<std::string> pellet;  // checked against the scene's pellets once it is read
  SectionCoordinate coordinate = SectionCoordinate::dphi;
};

// Adds --plot, --pellet and --coordinate, bound to `o` (which must outlive the parse).
void add_sweep_plot_options(CLI::App& command, SweepPlotOptions& o);

// The plot the options ask for, for `scene` (which has a sweep); when `drawn`, also whether the
// sweep computes what it draws (the Lyapunov plots need "lyapunov": true). Empty after printing
// why not (naming --plot, --pellet or the sweep's field).
std::optional<SweepPlot> sweep_plot_of(const SweepPlotOptions& o, const Scene& scene, bool drawn);

// The sweep's result drawn as `plot`; empty after printing why it cannot be.
std::optional<std::string> sweep_image(const Scene& scene, const SweepPlot& plot,
                                       const SweepResult& result, ImageFormat format);

}  // namespace vibro
