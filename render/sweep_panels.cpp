// The panels that draw a sweep. Point clouds (bifurcation diagram, section, impact map) draw every
// section point of one pellet as a small translucent dot, so that a period-p motion reads as p
// dots and a chaotic one as a dense cloud; continuation swept down is told apart from swept up
// (hysteresis shows as two branches over one range), and the points of runs the trust check
// could not vouch for are drawn hollow. The regime map colours each cell of a 2-D sweep by the
// period of its motion.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>

#include "core/model/model.h"
#include "render/axes.h"
#include "render/layout.h"
#include "render/legend.h"
#include "render/markers.h"
#include "render/panel.h"
#include "render/parameter_label.h"
#include "render/parameter_range.h"
#include "render/sweep_cells.h"
#include "render/text.h"

namespace vibro::render {

namespace {

// Where a point goes in a point-cloud panel, and what the axes say.
struct Cloud {
  std::function<double(const SweepRun&, const SectionPoint&)> x, y;
  std::string x_label, y_label;
  bool x_angle = false, y_angle = false;
  std::string title;
};

Cloud cloud_of(const SweepPlot& spec, const SweepSpec& sweep) {
  const bool stroboscopic = sweep.section == SectionKind::stroboscopic;
  const std::string where = stroboscopic ? " at t = kT" : " before impact";
  const std::string section = stroboscopic ? "stroboscopic" : "impact";
  const std::string pellet = "pellet " + std::to_string(spec.pellet + 1);
  auto phi = [](const SweepRun&, const SectionPoint& p) { return wrap_angle(p.phi); };
  auto dphi = [](const SweepRun&, const SectionPoint& p) { return p.dphi; };
  Cloud c;
  switch (spec.view) {
    case SweepView::section:
      c = {phi,
           dphi,
           std::string("\u03c6") + where + " [rad]",
           std::string("\u03c6\u0307") + where + " [rad/s]",
           true,
           false,
           "Poincar\u00e9 section (" + section + "), " + pellet};
      break;
    case SweepView::impact_map:
      c = {[](const SweepRun&, const SectionPoint& p) { return p.phase; },
           dphi,
           "phase of the forcing at impact, \u03a9t mod 2\u03c0 [rad]",
           "\u03c6\u0307 before impact [rad/s]",
           true,
           false,
           "Impact map, " + pellet};
      break;
    default: {
      const bool angle = spec.coordinate == SectionCoordinate::phi;
      c = {[](const SweepRun& r, const SectionPoint&) { return r.value; },
           angle ? phi : dphi,
           parameter_label(sweep.axis.parameter),
           std::string(angle ? "\u03c6" : "\u03c6\u0307") + where + (angle ? " [rad]" : " [rad/s]"),
           false,
           angle,
           "Bifurcation diagram, " + section + " section, " + pellet};
    }
  }
  return c;
}

// The periods a regime map tells apart: 1 … 8 each, every longer one as one class (9), and 0
// (not periodic).
constexpr int kLongestPeriodShown = 8;
int period_class(int period) { return std::min(period, kLongestPeriodShown + 1); }

// Distinct colours for periods 1 … 8 (Okabe and Ito's, told apart with any colour vision), a
// dark wine for the longer periods, light grey for none.
Colour period_colour(int period) {
  static constexpr Colour colours[] = {rgb(0x0072b2), rgb(0xe69f00), rgb(0x009e73),
                                       rgb(0xcc79a7), rgb(0xd55e00), rgb(0x56b4e9),
                                       rgb(0xf0e442), rgb(0x444444), rgb(0x882255)};
  const int c = period_class(period);
  return c >= 1 ? colours[c - 1] : rgb(0xbbbbbb);
}

std::string period_label(int period_class) {
  if (period_class == 0) return "not periodic";
  if (period_class > kLongestPeriodShown) return "period > " + std::to_string(kLongestPeriodShown);
  return "period " + std::to_string(period_class);
}

}  // namespace

void draw_sweep_points_panel(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& swept,
                             const BranchData* over) {
  const SweepResult& sweep = swept.result;
  const SweepSpec& spec = swept.spec;
  const Style& style = in.style;
  const int pellet = in.spec.pellet;
  const Cloud cloud = cloud_of(in.spec, spec);

  Range x, y;
  for (const SweepRun& run : sweep.runs)
    for (const SectionPoint& p : run.points)
      if (p.pellet == pellet) {
        x.include(cloud.x(run, p));
        y.include(cloud.y(run, p));
      }
  if (x.empty()) x = {-1.0, 1.0};
  if (x.span() <= 0.0) x = {x.lo - 0.5, x.lo + 0.5};
  x = padded(x, 0.02);
  if (in.spec.view == SweepView::impact_map) x = {0.0, 2.0 * M_PI};
  if (in.spec.view == SweepView::bifurcation) x = bifurcation_range(spec.axis);
  // A continued branch drawn over a bifurcation diagram of the same parameter.
  const OrbitBranch* branch = in.spec.view == SweepView::bifurcation && over &&
                                      over->continuation.parameter == spec.axis.parameter
                                  ? &over->branch
                                  : nullptr;
  if (branch) {
    const Range b = branch_range(*branch, pellet, in.spec.coordinate);
    if (!b.empty()) {
      y.include(b.lo);
      y.include(b.hi);
    }
  }
  if (y.empty()) y = {-1.0, 1.0};
  if (y.span() <= 0.0) y = {y.lo - 0.5, y.lo + 0.5};
  const Rect& area = in.layout.plots.front();
  const Axis ax = make_axis(x, style.axis_room(area.w), cloud.x_angle, cloud.x_label);
  const Axis ay =
      make_axis(padded(y, 0.05), style.axis_room(area.h), cloud.y_angle, cloud.y_label, true);
  const Transform tr(area, ax.range, ay.range);

  draw_grid(cr, tr, ax, ay, style);
  cairo_save(cr);
  clip_to(cr, area);
  // A dot a little over a pixel wide: dense clouds darken where points pile up.
  const double r = style.px(1.3);
  bool any_backward = false, any_untrusted = false;
  Obstacles avoid;
  std::vector<Point> drawn;
  for (const SweepRun& run : sweep.runs) {
    const Colour c = series_colour(run.direction < 0 ? 1 : 0);
    for (const SectionPoint& p : run.points) {
      if (p.pellet != pellet) continue;
      any_backward = any_backward || run.direction < 0;
      any_untrusted = any_untrusted || !p.trusted;
      const Point at = tr.to_pixel(cloud.x(run, p), cloud.y(run, p));
      add_marker_path(cr, at, MarkerShape::circle, r);
      if (p.trusted) {
        cairo_set_source_rgba(cr, c.r, c.g, c.b, 0.55);
        cairo_fill(cr);
      } else {
        cairo_set_source_rgba(cr, c.r, c.g, c.b, 0.8);
        cairo_set_line_width(cr, style.px(0.6));
        cairo_stroke(cr);
      }
      drawn.push_back(at);
    }
  }
  avoid.lines.push_back(drawn);
  std::vector<LegendEntry> legend;
  if (branch)
    draw_branch_curve(cr, tr, *branch, in.model, pellet, in.spec.coordinate, style, legend, avoid);
  if (any_backward) {
    legend.push_back({"swept up", series_colour(0), Swatch::marker});
    legend.push_back({"swept down", series_colour(1), Swatch::marker});
  }
  if (any_untrusted)
    legend.push_back(
        {"not trusted", {1.0, 1.0, 1.0, 1.0}, Swatch::marker, MarkerShape::circle, kInk});
  cairo_restore(cr);
  // Unclipped: with no free corner the legend stands above the plot.
  draw_legend(cr, legend, area, avoid, style);
  draw_frame(cr, tr, ax, ay, style);
  draw_title(cr, in.layout.title_anchor, in.spec.title.empty() ? cloud.title : in.spec.title,
             style);
}

void draw_regime_map_panel(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep,
                           const MapOverlay& over) {
  const CellMap map = draw_cells(cr, in, sweep, [](const SweepRun& run) {
    return run.at_rest ? Colour{1.0, 1.0, 1.0, 1.0} : period_colour(run.period);
  });
  std::vector<int> periods;
  bool rest = false;
  for (const SweepRun& run : sweep.result.runs) {
    if (!shown_in_cell(run)) continue;
    rest = rest || run.at_rest;
    const int c = period_class(run.period);
    if (!run.at_rest && std::find(periods.begin(), periods.end(), c) == periods.end())
      periods.push_back(c);
  }
  std::sort(periods.begin(), periods.end(),
            [](int p, int q) { return (p == 0 ? 1000 : p) < (q == 0 ? 1000 : q); });
  std::vector<LegendEntry> legend;
  for (int p : periods) legend.push_back({period_label(p), period_colour(p), Swatch::area});
  if (rest)
    legend.push_back({"at rest", {1.0, 1.0, 1.0, 1.0}, Swatch::area, MarkerShape::circle, kGuide});
  if (map.untrusted) legend.push_back({"not trusted", kInk, Swatch::line});
  if (over) {
    cairo_save(cr);
    clip_to(cr, in.layout.plots.front());
    over(map.tr, legend);
    cairo_restore(cr);
  }
  draw_frame(cr, map.tr, map.x, map.y, in.style);
  draw_legend(cr, legend, legend_column(in), {}, in.style);
  draw_title(cr, in.layout.title_anchor,
             in.spec.title.empty() ? "Regime map: the period of the motion" : in.spec.title,
             in.style);
}

}  // namespace vibro::render

namespace vibro {

std::optional<ParameterAxis> parameter_axis(const FigureSpec& figure, const SweepSpec& spec) {
  if (figure.plots.empty()) return std::nullopt;
  const auto* plot = std::get_if<SweepPlot>(&figure.plots.front());
  if (!plot || plot->view == SweepView::section || plot->view == SweepView::impact_map)
    return std::nullopt;
  const bool map = map_view(plot->view);
  const render::Rect area = render::figure_layout(figure).front().plots.front();
  const render::Range x =
      map ? render::cell_range(spec.axis) : render::bifurcation_range(spec.axis);
  return ParameterAxis{area.x, area.y, area.w, area.h, x.lo, x.hi};
}

}  // namespace vibro
