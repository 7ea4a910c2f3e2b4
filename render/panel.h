// What every panel drawer gets: its spec, the model and run, where to draw, and the style.
// The figure checks the spec against the model and the run before any drawer runs, so drawers
// may assume valid pellet indices and recorded tracks.
#pragma once

#include <cairo.h>

#include "core/model.h"
#include "core/result.h"
#include "render/figure.h"
#include "render/layout.h"
#include "render/plot_spec.h"
#include "render/style.h"

namespace vibro::render {

struct PanelInput {
  const PlotSpec& spec;
  const Model& model;
  const RunResult& run;
  const PanelLayout& layout;
  const Style& style;
  const PanelData& data;  // for work-precision and bifurcation panels
};

// The (φ, φ̇) portrait of one pellet: numbered branches, impacts, limiters, optional overlays.
void draw_phase_panel(cairo_t* cr, const PanelInput& in);

// φ(t) of the listed pellets (and φ̇(t) below it when asked), limiter angles, event marks.
void draw_time_panel(cairo_t* cr, const PanelInput& in);

// log10 error against log10 median run time, one line per method, points labelled by rtol.
void draw_work_precision_panel(cairo_t* cr, const PanelInput& in);

// A sweep's section points of one pellet as a cloud of dots: against the swept parameter
// (bifurcation), in the (φ, φ̇) plane (section) or against the forcing phase (impact map);
// continuation forward and backward told apart, runs not trusted hollow.
void draw_sweep_points_panel(cairo_t* cr, const PanelInput& in);

// A 2-D sweep's cells coloured by the period of the motion, with a legend of periods.
void draw_regime_map_panel(cairo_t* cr, const PanelInput& in);

}  // namespace vibro::render
