// What every panel drawer gets: its plot (one kind's struct), the model and run, where to draw,
// and the style; and, for the kinds that draw more than the run, that data as references. The
// figure checks the plot against the model and the run, and that its data is given, before any
// drawer runs, so drawers may assume valid pellet indices and recorded tracks.
#pragma once

#include <cairo.h>

#include <functional>
#include <vector>

#include "core/model/model.h"
#include "core/run/result.h"
#include "render/figure.h"
#include "render/layout.h"
#include "render/legend.h"
#include "render/plot_spec.h"
#include "render/style.h"
#include "render/transform.h"

namespace vibro::render {

template <class Plot>
struct PanelInput {
  const Plot& spec;
  const Model& model;
  const RunResult& run;
  const PanelLayout& layout;
  const Style& style;
  std::vector<PlotAxes>* plot_axes = nullptr;  // phase and time panels add where they lie
};

// The (φ, φ̇) portrait of one pellet: numbered branches, impacts, limiters, optional overlays.
void draw_phase_panel(cairo_t* cr, const PanelInput<PhasePlot>& in);

// φ(t) of the listed pellets (and φ̇(t) below it when asked), limiter angles, event marks.
void draw_time_panel(cairo_t* cr, const PanelInput<TimePlot>& in);

// log10 error against log10 median run time, one line per method, points labelled by rtol.
void draw_work_precision_panel(cairo_t* cr, const PanelInput<WorkPrecisionPlot>& in,
                               const WorkPrecisionReport& report);

// A sweep's section points of one pellet as a cloud of dots: against the swept parameter
// (bifurcation), in the (φ, φ̇) plane (section) or against the forcing phase (impact map);
// continuation forward and backward told apart, runs not trusted hollow. A bifurcation diagram
// draws `over` on it when given and continued in the swept parameter.
void draw_sweep_points_panel(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep,
                             const BranchData* over);

// The continued branch of a periodic motion over its parameter (stable solid, unstable dashed,
// neutral dotted, bifurcations marked and named).
void draw_branch_panel(cairo_t* cr, const PanelInput<BranchPlot>& in, const BranchData& branch);

// The branch into a plot's transform, with its legend entries and what the legend should not
// hide; and the range of its section coordinate, for one pellet.
// The line is broken where an impact crosses the section time (render/branch_marks.h), and a
// bifurcation outside the plot is named in the legend with its value.
void draw_branch_curve(cairo_t* cr, const Transform& tr, const OrbitBranch& branch,
                       const Model& model, int pellet, SectionCoordinate coordinate,
                       const Style& style, std::vector<LegendEntry>& legend, Obstacles& avoid);
Range branch_range(const OrbitBranch& branch, int pellet, SectionCoordinate coordinate);

// A 2-D sweep's cells coloured by the period of the motion, with a legend of periods; `over`,
// when given, draws on the cells in the map's transform and adds its legend entries.
using MapOverlay = std::function<void(const Transform&, std::vector<LegendEntry>&)>;
void draw_regime_map_panel(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep,
                           const MapOverlay& over = {});

// The bifurcation curves followed from a branch, in the plane of the continuation's parameter
// (x) and the second one (y), each kind by its dash; alone, or into a given transform with the
// parameters swapped when the map's axes are (core/analysis/bifurcation_curve.h).
void draw_curves_panel(cairo_t* cr, const PanelInput<BranchPlot>& in, const BranchData& branch);
void draw_bifurcation_curves(cairo_t* cr, const Transform& tr,
                             const std::vector<BifurcationCurve>& curves, bool swapped,
                             const Style& style, std::vector<LegendEntry>& legend);

// A basin sweep's cells coloured by attractor (SweepRun::attractor), with a legend of the
// attractors' periods and impacts per period. The sweep classified them (validate_sweep_plot).
void draw_basins_panel(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep);

// A sweep's largest Lyapunov exponents against the swept parameter, one line per direction of
// continuation, with the zero line; and a 2-D sweep's cells coloured by it, with a colour bar.
// The sweep computed them (validate_sweep_plot).
void draw_lyapunov_panel(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep);
void draw_lyapunov_map_panel(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep);

}  // namespace vibro::render
