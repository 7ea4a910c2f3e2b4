// The cells of a map of a sweep (the regime map, the Lyapunov map): one per pair of values,
// filled edge to edge, so that every pixel inside the frame is data and the legend goes beside
// the plot, in the column the layout keeps free for it (kMapLegendColumn).
#pragma once

#include <cairo.h>

#include <functional>

#include "render/axes.h"
#include "render/panel.h"

namespace vibro::render {

// The run a cell shows: the first start, swept up (one per cell).
bool shown_in_cell(const SweepRun& run);

struct CellMap {
  Axis x, y;
  Transform tr;
  bool untrusted = false;  // some cell is struck through
};

// Axes of the sweep's parameters (a 1-D sweep: one row), and every shown run's cell filled in
// the colour `colour_of` gives it, struck through where the trust check could not vouch for the
// run. The frame is the caller's, drawn over the cells.
CellMap draw_cells(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep,
                   const std::function<Colour(const SweepRun&)>& colour_of);

// The column right of the plot area that a map keeps for its legend.
Rect legend_column(const PanelInput<SweepPlot>& in);

}  // namespace vibro::render
