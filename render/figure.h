// The public entry point of render/: a figure (one or more panels in a grid) drawn from a run,
// as PNG, SVG or PDF bytes from the same drawing code (text stays text in SVG and PDF).
//
// What the caller must provide:
//  - a RunResult whose `tracks` hold every pellet a panel draws (phase and cylinder panels:
//    `pellet`; time panels: `pellets`, or all of the model's pellets when that list is empty;
//    mechanism panels: all of them, the run reaching their `t`);
//  - events in time order (impacts are marked from them).
// Each panel draws the part of the run inside its [t_from, t_to] (s). Errors are values: nothing
// throws out of these functions.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/analysis/bifurcation_curve.h"
#include "core/analysis/orbit_continuation.h"
#include "core/analysis/sweep.h"
#include "core/analysis/work_precision.h"
#include "core/model/model.h"
#include "core/run/limits.h"
#include "core/run/result.h"
#include "core/run/validate.h"
#include "render/figure_size.h"
#include "render/plot_spec.h"

namespace vibro {

enum class ImageFormat { png, svg, pdf };

// "png", "svg", "pdf", or nothing.
std::optional<ImageFormat> image_format_named(std::string_view name);
// The format a file name asks for by its extension (".png", ".svg", ".pdf"), or nothing.
std::optional<ImageFormat> image_format_of_file(std::string_view path);

// Where a phase or time panel's plot lies on the image and what its axes span, so that a point
// of the image names a state or a time: the web page starts a pellet where a portrait is clicked,
// and moves markers over the image as it animates the run.
enum class PlotAxesKind { phase, time };
struct PlotAxes {
  // phase: x φ (rad), y φ̇ (rad/s); time: x t (s), y φ (rad)
  PlotAxesKind kind = PlotAxesKind::phase;
  int pellet = -1;                                          // phase: the pellet drawn
  double left = 0.0, top = 0.0, width = 0.0, height = 0.0;  // the plot area, image pixels
  double x_lo = 0.0, x_hi = 0.0;                            // at the left and right edges
  double y_lo = 0.0, y_hi = 0.0;                            // at the bottom and top edges
};

struct RenderResult {
  std::vector<std::uint8_t> bytes;
  std::string content_type;  // "image/png", "image/svg+xml" or "application/pdf"
  // The offending field as the scene JSON spells it ("width", "plots[1].pellet") and what was
  // expected; FieldError is core's error type, so the server reports both kinds alike.
  std::optional<FieldError> error;
  std::vector<PlotAxes> plot_axes;  // one per phase or time panel (its φ plot), in order

  bool ok() const { return !error; }
};

// Checks a figure against the model before any simulation: its size and panel count against
// `limits` (check_figure_size, Limits::plots), each plot (validate_plot, render/plot_validate.h;
// instants only ≥ 0: the scene reader holds them to t_end), and 3-D panels (PNG only, and only in
// builds with 3-D).
std::optional<FieldError> validate_figure(const FigureSpec& figure, const Model& model,
                                          ImageFormat format, const Limits& limits = {});

// Whether a sweep can be drawn as a plot of this kind, before it runs: the Lyapunov plots need
// the exponents ("sweep.lyapunov": true), and a line of them against one parameter a 1-D sweep
// (a 2-D one is drawn as a Lyapunov map). The field named is the sweep's.
std::optional<FieldError> validate_sweep_plot(SweepView view, const SweepSpec& spec);

// A sweep and the spec it ran, drawn together.
struct SweepData {
  const SweepSpec& spec;
  const SweepResult& result;
};

// A continued periodic motion and the continuation that made it; with the bifurcation curves
// followed from it in a second parameter, when a bifurcation_curves panel draws them.
struct BranchData {
  const OrbitBranch& branch;
  const ContinuationSpec& continuation;
  const std::vector<BifurcationCurve>* curves = nullptr;
  const FollowSpec* follow = nullptr;
};

// What panels that draw more than the run draw, each part whole or absent: work-precision panels
// a report, sweep panels a sweep, branch panels a continued periodic motion (over the sweep
// beneath it, if given; a bifurcation panel draws a given branch over its points).
struct PanelData {
  const WorkPrecisionReport* work_precision = nullptr;
  std::optional<SweepData> sweep = std::nullopt;
  std::optional<BranchData> branch = std::nullopt;
};

// Validates, then draws every panel. Also errors: a pellet whose track the run did not record,
// a panel whose data is not given.
RenderResult render_figure(const FigureSpec& figure, const Model& model, const RunResult& run,
                           ImageFormat format, const PanelData& data = {});

// Where the swept parameter lies in the first panel of a figure drawn with a bifurcation,
// regime-map or Lyapunov panel first: its plot area in image pixels and the parameter values at its
// left and right edges, so a click on the image can name a value. Nothing for other panels.
struct ParameterAxis {
  double left = 0.0, top = 0.0, width = 0.0, height = 0.0;  // px
  double from = 0.0, to = 0.0;  // the parameter at the left and right edges
};
std::optional<ParameterAxis> parameter_axis(const FigureSpec& figure, const SweepSpec& spec);

// Whether this build can draw 3-D (cylinder) panels.
bool cylinder_panels_available();

std::string_view content_type(ImageFormat format);

}  // namespace vibro
