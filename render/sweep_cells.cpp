#include "render/sweep_cells.h"

#include <algorithm>
#include <cmath>

#include "render/parameter_label.h"
#include "render/parameter_range.h"
#include "render/text.h"

namespace vibro::render {
namespace {

Point on_pixels(Point p) { return {std::round(p.x), std::round(p.y)}; }

}  // namespace

bool shown_in_cell(const SweepRun& run) { return run.start == 0 && run.direction >= 0; }

CellMap draw_cells(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep,
                   const std::function<Colour(const SweepRun&)>& colour_of) {
  const SweepSpec& spec = sweep.spec;
  const SweepAxis& a = spec.axis;
  const SweepAxis one{"", 0.0, 0.0, 1};
  const SweepAxis& b = spec.axis2 ? *spec.axis2 : one;
  const Range x = cell_range(a), y = cell_range(b);
  const Rect& area = in.layout.plots.front();
  CellMap map{make_axis(x, in.style.axis_room(area.w), false, parameter_label(a.parameter)),
              make_axis(y, in.style.axis_room(area.h), false,
                        spec.axis2 ? parameter_label(b.parameter) : "", true),
              Transform(area, x, y)};
  const double w = x.span() / std::max(a.count, 1), h = y.span() / std::max(b.count, 1);
  for (const SweepRun& run : sweep.result.runs) {
    if (!shown_in_cell(run)) continue;
    // Cells on whole pixels, their edges computed alike from the index, filled without
    // antialiasing: neighbours meet without a seam or an overlap.
    const int i = cell_index(a, run.value), j = cell_index(b, run.value2);
    const Point lo = on_pixels(map.tr.to_pixel(x.lo + i * w, y.lo + j * h));
    const Point hi = on_pixels(map.tr.to_pixel(x.lo + (i + 1) * w, y.lo + (j + 1) * h));
    cairo_rectangle(cr, lo.x, hi.y, hi.x - lo.x, lo.y - hi.y);
    set_colour(cr, colour_of(run));
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    cairo_fill(cr);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
    if (!run.trusted) {  // struck through: the trust check could not vouch for it
      cairo_move_to(cr, lo.x, lo.y);
      cairo_line_to(cr, hi.x, hi.y);
      set_colour(cr, kInk);
      cairo_set_line_width(cr, in.style.px(0.5));
      cairo_stroke(cr);
      map.untrusted = true;
    }
  }
  return map;
}

Rect legend_column(const PanelInput<SweepPlot>& in) {
  const Rect& area = in.layout.plots.front();
  const double column = in.spec.view == SweepView::basins ? kBasinsLegendColumn : kMapLegendColumn;
  return {area.right(), area.y, in.style.px(column), area.h};
}

}  // namespace vibro::render
