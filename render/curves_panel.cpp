// Bifurcation curves (core/analysis/bifurcation_curve.h) in the plane of the continuation's
// parameter and the second one: each curve a line, its kind told by its dash and named in the
// legend.
// Drawn alone or over the regime map of a 2-D sweep of the same two parameters, where a period
// doubling curve must bound the cells of doubled period.
#include <string>

#include "render/axes.h"
#include "render/legend.h"
#include "render/panel.h"
#include "render/parameter_label.h"
#include "render/text.h"

namespace vibro::render {
namespace {

// Ink over any cell colour of a regime map, told apart by the dash: solid for a period doubling,
// long dashes for a fold, short ones for a grazing.
struct CurveLook {
  const char* name;
  double dash;  // px at scale 1; 0: solid
};

CurveLook look_of(BifurcationKind kind) {
  switch (kind) {
    case BifurcationKind::fold:
      return {"fold", 8.0};
    case BifurcationKind::period_doubling:
      return {"period doubling", 0.0};
    case BifurcationKind::neimark_sacker:
      return {"Neimark\u2013Sacker", 2.0};
    case BifurcationKind::grazing:
      return {"grazing", 3.0};
  }
  return {"?", 0.0};
}

}  // namespace

void draw_bifurcation_curves(cairo_t* cr, const Transform& tr,
                             const std::vector<BifurcationCurve>& curves, bool swapped,
                             const Style& style, std::vector<LegendEntry>& legend) {
  for (const BifurcationCurve& c : curves) {
    if (c.points.empty()) continue;
    const CurveLook look = look_of(c.kind);
    for (const CurvePoint& p : c.points) {
      const Point at = swapped ? tr.to_pixel(p.value2, p.value) : tr.to_pixel(p.value, p.value2);
      if (&p == &c.points.front())
        cairo_move_to(cr, at.x, at.y);
      else
        cairo_line_to(cr, at.x, at.y);
    }
    // A white casing under the line keeps it readable over coloured cells.
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    set_colour(cr, {1.0, 1.0, 1.0, 1.0});
    cairo_set_line_width(cr, style.px(4.5));
    cairo_stroke_preserve(cr);
    const double dash[] = {style.px(look.dash), style.px(look.dash * 0.6)};
    cairo_set_dash(cr, dash, look.dash > 0.0 ? 2 : 0, 0.0);
    set_colour(cr, kInk);
    cairo_set_line_width(cr, style.px(2.2));
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    legend.push_back({look.name, kInk, look.dash > 0.0 ? Swatch::dashed_line : Swatch::line});
  }
}

void draw_curves_panel(cairo_t* cr, const PanelInput<BranchPlot>& in, const BranchData& data) {
  const Style& style = in.style;
  Range x, y;
  for (const BifurcationCurve& c : *data.curves)
    for (const CurvePoint& p : c.points) {
      x.include(p.value);
      y.include(p.value2);
    }
  if (x.empty()) x = {-1.0, 1.0};
  if (x.span() <= 0.0) x = {x.lo - 0.5, x.lo + 0.5};
  if (y.empty()) y = {data.follow->from, data.follow->to};
  if (y.span() <= 0.0) y = {y.lo - 0.5, y.lo + 0.5};
  const Rect& area = in.layout.plots.front();
  const Axis ax = make_axis(padded(x, 0.05), style.axis_room(area.w), false,
                            parameter_label(data.continuation.parameter));
  const Axis ay = make_axis(padded(y, 0.05), style.axis_room(area.h), false,
                            parameter_label(data.follow->parameter2), true);
  const Transform tr(area, ax.range, ay.range);
  draw_grid(cr, tr, ax, ay, style);
  cairo_save(cr);
  clip_to(cr, area);
  std::vector<LegendEntry> legend;
  draw_bifurcation_curves(cr, tr, *data.curves, false, style, legend);
  cairo_restore(cr);
  draw_frame(cr, tr, ax, ay, style);
  draw_legend(cr, legend, {area.right(), area.y, style.px(kMapLegendColumn), area.h}, {}, style);
  draw_title(cr, in.layout.title_anchor,
             in.spec.title.empty() ? "Bifurcation curves" : in.spec.title, style);
}

}  // namespace vibro::render
