#include "render/layout.h"

#include <algorithm>
#include <cmath>

namespace vibro::render {
namespace {

// Margins in units of the style's scale: room for tick labels and the axis label on the left
// and below, the title above, and the last x tick label's overhang on the right.
constexpr double kLeft = 86.0, kRight = 24.0, kTop = 40.0, kBottom = 60.0, kStackGap = 14.0;
constexpr double kTitleTop = 9.0;

}  // namespace

std::vector<Rect> grid_cells(int count, int width, int height) {
  if (count <= 0) return {};
  const bool wide = width >= height;
  int columns = 1;
  if (count == 2) {
    columns = wide ? 2 : 1;
  } else if (count <= 4 && count > 2) {
    columns = 2;
  } else if (count > 4) {
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    columns = wide ? side : (count + side - 1) / side;
  }
  const int rows = (count + columns - 1) / columns;
  const double w = static_cast<double>(width) / columns, h = static_cast<double>(height) / rows;
  std::vector<Rect> cells;
  for (int i = 0; i < count; ++i)
    cells.push_back({std::floor((i % columns) * w), std::floor((i / columns) * h), std::floor(w),
                     std::floor(h)});
  // The panels of a last, partly filled row share its whole width (a φ(t) plot under two
  // portraits spans the figure instead of leaving a blank cell).
  const int last_row = count - (rows - 1) * columns;
  if (rows > 1 && last_row < columns) {
    const double lw = static_cast<double>(width) / last_row;
    for (int k = 0; k < last_row; ++k) {
      Rect& c = cells[(rows - 1) * columns + k];
      c.x = std::floor(k * lw);
      c.w = std::floor(lw);
    }
  }
  return cells;
}

PanelLayout panel_layout(Rect cell, const Style& style, int stacked, double legend_column,
                         double legend_strip) {
  PanelLayout layout{cell, {cell.x + 0.5 * cell.w, cell.y + style.px(kTitleTop)}, {}};
  const int n = std::max(1, stacked);
  // The margins as the style asks, or what a cell too small for them leaves: each plot area
  // keeps at least a pixel inside its cell (whole pixels: the cell's sides are).
  const double left = std::min(cell.x + style.px(kLeft), cell.right() - 1.0);
  const double top = std::min(cell.y + style.px(kTop + legend_strip), cell.bottom() - n);
  const double width =
      std::clamp(cell.w - style.px(kLeft + kRight + legend_column), 1.0, cell.right() - left);
  const double height =
      std::clamp(cell.h - style.px(kTop + kBottom + legend_strip), 1.0 * n, cell.bottom() - top);
  const double gap = std::min(style.px(kStackGap), (height - n) / std::max(1, n - 1));
  const double each = std::max(1.0, (height - gap * (n - 1)) / n);
  for (int i = 0; i < n; ++i)
    layout.plots.push_back({std::round(left), std::round(top + i * (each + gap)), std::round(width),
                            std::round(each)});
  layout.title_anchor.x = layout.plots.front().x + 0.5 * layout.plots.front().w;
  return layout;
}

std::vector<PanelLayout> figure_layout(const FigureSpec& figure) {
  const Style style = style_for(figure);
  const auto cells = grid_cells(static_cast<int>(figure.plots.size()), figure.width, figure.height);
  std::vector<PanelLayout> layouts;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const PlotSpec& plot = figure.plots[i];
    if (std::holds_alternative<CylinderPlot>(plot) || std::holds_alternative<MechanismPlot>(plot)) {
      const Rect& c = cells[i];
      const double top = std::min(style.px(kTop), c.h - 1.0);
      layouts.push_back(
          {c, {c.x + 0.5 * c.w, c.y + style.px(kTitleTop)}, {{c.x, c.y + top, c.w, c.h - top}}});
    } else {
      const auto* time = std::get_if<TimePlot>(&plot);
      const int stacked = time && time->show_dphi ? 2 : 1;
      const auto* sweep = std::get_if<SweepPlot>(&plot);
      const auto* curves = std::get_if<BranchPlot>(&plot);
      const bool map = (sweep && map_view(sweep->view)) || (curves && curves->curves);
      const double column = !map                                        ? 0.0
                            : sweep && sweep->view == SweepView::basins ? kBasinsLegendColumn
                                                                        : kMapLegendColumn;
      layouts.push_back(panel_layout(cells[i], style, stacked, column));
    }
  }
  return layouts;
}

}  // namespace vibro::render
