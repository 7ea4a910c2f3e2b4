// Where things go: the grid of panels in a figure and the plot areas inside a panel. Margins are
// fixed multiples of the style's scale, so that tests can compute the plot area from the spec.
#pragma once

#include <vector>

#include "render/geometry.h"
#include "render/plot_spec.h"
#include "render/style.h"

namespace vibro::render {

// Cells of a figure of `count` panels, in reading order: one fills the figure; two sit side by
// side in a wide figure and stacked in a tall one; three or four make 2×2; more a near-square
// grid with at least as many columns as rows when the figure is wide.
std::vector<Rect> grid_cells(int count, int width, int height);

struct PanelLayout {
  Rect cell;
  Point title_anchor;       // top centre of the title
  std::vector<Rect> plots;  // plot areas, top to bottom; stacked ones share the x axis
};

// A 2-D panel with `stacked` plot areas (1, or 2 for φ(t) over φ̇(t)) above a shared x axis,
// `legend_column` pixels (at scale 1) kept free right of the plot for a legend beside the data,
// or `legend_strip` pixels above it for a legend over the data.
PanelLayout panel_layout(Rect cell, const Style& style, int stacked, double legend_column = 0.0,
                         double legend_strip = 0.0);

// The width (at scale 1) a map of a sweep (regime or Lyapunov map) keeps right of its plot for
// its legend or colour bar: every cell is data, so no corner of the plot is free for it.
inline constexpr double kMapLegendColumn = 160.0;
// The basins' legend names each attractor's period and impacts: a wider column.
inline constexpr double kBasinsLegendColumn = 250.0;

// The layout of every panel of a figure: 3-D panels and mechanism sketches (no axes) get one plot
// area, the rest of the cell below the title.
std::vector<PanelLayout> figure_layout(const FigureSpec& figure);

}  // namespace vibro::render
