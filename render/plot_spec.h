// What a scene asks to be drawn: the `plots` list of API.md, as plain values, one struct per kind
// holding the fields that kind reads. The scene reader (io/plot_json.h) creates them; render/
// draws them. Indices count from 0.
//
// A new kind: its struct here and in the PlotSpec variant, its reader and writer in
// io/plot_json.cpp, its checks in render/plot_validate.cpp, its drawer (render/panel.h and its
// own file) and its case in render/figure.cpp; the compiler names every visitor that misses it.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/run/result.h"

namespace vibro {

// The section coordinate a bifurcation diagram or a branch draws against the parameter.
enum class SectionCoordinate { dphi, phi };

struct Camera {
  double azimuth_deg = 35.0;
  double elevation_deg = 25.0;
  double distance = 5.0;  // in cylinder radii; sets the strength of the perspective
};

// Axis limits a scene sets, lo < hi.
struct AxisLimits {
  double lo = 0.0;
  double hi = 1.0;
};

// The part of the run a panel draws, s.
struct TimeWindow {
  double t_from = 0.0;
  double t_to = std::numeric_limits<double>::infinity();  // clipped to t_end
};

// (φ, φ̇) of one pellet, branches told apart.
// How a phase portrait colours its branches: each its own colour (numbered), all one colour, or
// by the time each begins, from dark blue (early) to yellow (late), for a long run that settles.
enum class PhaseColours { branch, one, time };

struct PhasePlot : TimeWindow {
  int pellet = 0;
  PhaseColours colours = PhaseColours::branch;  // "one" and "time" number no branch
  std::vector<int> branches;  // only these motion intervals (numbered from 1); empty: all
  std::optional<PhasePoint> first_integral_through;  // the exact unforced curve through it
  bool friction_zone = false;            // shade |φ| ≤ α0 (mod 2π) where a pellet can rest
  bool wrap = false;                     // φ on one turn, [−π, π)
  bool branch_labels = true;             // number the branches
  std::optional<AxisLimits> phi_range;   // default: the data's
  std::optional<AxisLimits> dphi_range;  // default: the data's
  std::string title;                     // empty: a default title
};

// φ(t) (optionally φ̇(t) on a second axis) of the listed pellets.
struct TimePlot : TimeWindow {
  std::vector<int> pellets;  // empty: every pellet of the model
  bool show_dphi = false;
  std::optional<AxisLimits> phi_range;
  std::optional<AxisLimits> dphi_range;
  std::string title;
};

// 3-D (OSMesa): the trajectory of one pellet on the phase cylinder (cos φ, sin φ, φ̇).
struct CylinderPlot : TimeWindow {
  int pellet = 0;
  Camera camera;
  std::string title;
};

// The circle, limiters, pellets and forces at one instant, to scale (paper Fig. 1).
struct MechanismPlot {
  double t = 0.0;  // s, in [0, t_end]
  std::string title;
};

// Log error against log run time, one line per method: a sweep of runs, not the run. Its window
// is read and written back with the scene; only how far the scene's run goes depends on it.
struct WorkPrecisionPlot : TimeWindow {
  std::string title;
};

// How a sweep plot shows the sweep.
enum class SweepView {
  bifurcation,   // section points of one pellet against the swept parameter
  section,       // section points of one pellet in the (φ, φ̇) plane
  impact_map,    // impacts of one pellet: φ̇ before impact against the forcing phase
  regime_map,    // a 2-D sweep's cells coloured by the period of the motion
  lyapunov,      // a 1-D sweep's largest Lyapunov exponents against the swept parameter
  lyapunov_map,  // a 2-D sweep's cells coloured by the largest Lyapunov exponent
  basins,        // a sweep over initial states, its cells coloured by attractor
};

// Whether the view fills the sweep's cells edge to edge, its legend in a column beside them.
constexpr bool map_view(SweepView v) {
  return v == SweepView::regime_map || v == SweepView::lyapunov_map || v == SweepView::basins;
}

// A sweep drawn (the sweep's result, not the scene's run).
struct SweepPlot {
  SweepView view = SweepView::bifurcation;
  int pellet = 0;                                          // the point clouds
  SectionCoordinate coordinate = SectionCoordinate::dphi;  // bifurcation
  std::string title;
};

// A continued periodic motion against its parameter, stability and bifurcations marked; or,
// with `curves` (kind "bifurcation_curves"), the bifurcations followed in a second parameter, in
// the plane of the two (over the regime map of a 2-D sweep of the same two, when given).
struct BranchPlot {
  int pellet = 0;
  SectionCoordinate coordinate = SectionCoordinate::dphi;
  std::string title;
  bool curves = false;
};

using PlotSpec = std::variant<PhasePlot, TimePlot, CylinderPlot, MechanismPlot, WorkPrecisionPlot,
                              SweepPlot, BranchPlot>;

// A figure's size for print (a scene's "figure"): PDF and SVG pages of width_mm × height_mm, PNG
// images of width_mm / 25.4 · dpi pixels (and so on for the height), tick labels of font_pt
// points, the rest of the text and the lines in proportion (axis labels and titles a little
// larger, legends and branch numbers a little smaller).
struct PrintSize {
  double width_mm = 85.0;               // a journal's single column
  double height_mm = 85.0 * 2.0 / 3.0;  // read as two thirds of the width when not given
  double font_pt = 8.0;
  double dpi = 300.0;
};

struct FigureSpec {
  std::vector<PlotSpec> plots;
  // px: the image's pixels, and the units every panel is laid out in. With a print size they are
  // its pixels (render/figure_size.h, apply_print_size).
  int width = 1200;
  int height = 800;
  std::optional<PrintSize> print = std::nullopt;
};

}  // namespace vibro
