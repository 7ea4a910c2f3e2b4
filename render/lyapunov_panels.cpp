// The panels that draw a sweep's largest Lyapunov exponents (SweepSpec::lyapunov): against the
// swept parameter, a line through the runs of each direction of continuation with the zero line
// marked (what is drawn beside a bifurcation diagram: positive where the motion is chaotic); and
// over a 2-D sweep, a map of cells in a diverging scale centred at 0 with a colour bar. A run
// whose perturbations all die (every pellet held) has exponent −∞, which no scale holds: it is
// named in the legend, as are runs without an exponent.
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "render/colour_bar.h"
#include "render/markers.h"
#include "render/panel.h"
#include "render/parameter_label.h"
#include "render/parameter_range.h"
#include "render/polyline.h"
#include "render/sweep_cells.h"
#include "render/text.h"

namespace vibro::render {
namespace {

constexpr const char* kLyapunovLabel = "largest Lyapunov exponent [1/s]";
constexpr const char* kHeldLabel = "\u2212\u221e: pellets held";
constexpr Colour kNoValue = rgb(0x999999);
constexpr Colour kHeld{1.0, 1.0, 1.0, 1.0};

bool held(const SweepRun& run) {
  return run.lyapunov && std::isinf(*run.lyapunov) && *run.lyapunov < 0.0;
}
bool finite(const SweepRun& run) { return run.lyapunov && std::isfinite(*run.lyapunov); }

// One series of a Lyapunov plot in its direction's colour: a line through the runs' exponents,
// broken where a run has none, a dot on each (hollow where not trusted), and a triangle on the
// plot's bottom edge for each −∞.
void draw_series(cairo_t* cr, const Transform& tr, std::span<const SweepRun> runs,
                 const Style& style, Obstacles& avoid) {
  const Colour c = series_colour(runs.front().direction < 0 ? 1 : 0);
  const double r = style.px(3.0);
  std::vector<Point> line, filled, hollow, held_at;
  auto end_line = [&] {
    set_colour(cr, c);
    cairo_set_line_width(cr, style.curve_width());
    stroke_polyline(cr, line);
    avoid.lines.push_back(std::move(line));
    line.clear();
  };
  for (const SweepRun& run : runs) {
    if (!finite(run)) {
      if (held(run)) held_at.push_back({tr.px(run.value), tr.area().bottom() - 2.0 * r});
      end_line();
      continue;
    }
    line.push_back(tr.to_pixel(run.value, *run.lyapunov));
    (run.trusted ? filled : hollow).push_back(line.back());
  }
  end_line();
  draw_markers(cr, filled, MarkerShape::circle, r, c, c, 0.0);
  draw_markers(cr, hollow, MarkerShape::circle, r, {1.0, 1.0, 1.0, 1.0}, c, style.thin_width());
  draw_markers(cr, held_at, MarkerShape::triangle, r, c, c, 0.0);
  avoid.lines.push_back(held_at);
}

}  // namespace

void draw_lyapunov_map_panel(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep) {
  const Style& style = in.style;
  std::vector<double> values;
  bool any_held = false, any_missing = false;
  for (const SweepRun& run : sweep.result.runs) {
    if (!shown_in_cell(run)) continue;
    if (finite(run)) values.push_back(*run.lyapunov);
    any_held = any_held || held(run);
    any_missing = any_missing || (!finite(run) && !held(run));
  }
  const DivergingScale scale = diverging_scale(values);
  const CellMap map = draw_cells(cr, in, sweep, [&scale](const SweepRun& run) {
    return finite(run) ? scale.at(*run.lyapunov) : held(run) ? kHeld : kNoValue;
  });
  draw_frame(cr, map.tr, map.x, map.y, style);

  std::vector<LegendEntry> legend;
  if (any_held) legend.push_back({kHeldLabel, kHeld, Swatch::area, MarkerShape::circle, kGuide});
  if (any_missing) legend.push_back({"no value", kNoValue, Swatch::area});
  if (map.untrusted) legend.push_back({"not trusted", kInk, Swatch::line});
  // The bar over the column's height, above the legend of the cells it has no colour for.
  const Rect column = legend_column(in);
  const double below =
      legend.empty() ? 0.0 : legend_size(cr, legend, style).y + style.px(2.0 * kLegendInset);
  const Rect bar{column.x + style.px(kLegendInset + 6.0), column.y, style.px(16.0),
                 column.h - below};
  draw_colour_bar(cr, scale, bar, kLyapunovLabel, style);
  draw_legend(cr, legend, {column.x, bar.bottom(), column.w, below}, {}, style);
  draw_title(cr, in.layout.title_anchor,
             in.spec.title.empty() ? "Lyapunov map: the largest Lyapunov exponent" : in.spec.title,
             style);
}

void draw_lyapunov_panel(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep) {
  const std::vector<SweepRun>& runs = sweep.result.runs;
  const SweepSpec& spec = sweep.spec;
  const Style& style = in.style;
  Range y;
  y.include(0.0);  // the sign is the answer: the zero line is always on the plot
  for (const SweepRun& run : runs)
    if (finite(run)) y.include(*run.lyapunov);
  const Rect& area = in.layout.plots.front();
  const Axis ax = make_axis(bifurcation_range(spec.axis), style.axis_room(area.w), false,
                            parameter_label(spec.axis.parameter));
  const Axis ay = make_axis(padded(y, 0.08), style.axis_room(area.h), false, kLyapunovLabel, true);
  const Transform tr(area, ax.range, ay.range);

  draw_grid(cr, tr, ax, ay, style);
  cairo_save(cr);
  clip_to(cr, area);
  draw_zero_line(cr, tr, style);
  Obstacles avoid;
  // Runs come ordered by start, then direction, then value: each start's sweep in one direction
  // is one series.
  std::size_t first = 0;
  for (std::size_t k = 1; k <= runs.size(); ++k) {
    if (k < runs.size() && runs[k].start == runs[first].start &&
        runs[k].direction == runs[first].direction)
      continue;
    draw_series(cr, tr, std::span(runs).subspan(first, k - first), style, avoid);
    first = k;
  }
  const auto any = [&runs](auto&& test) { return std::any_of(runs.begin(), runs.end(), test); };
  std::vector<LegendEntry> legend;
  if (any([](const SweepRun& run) { return run.direction < 0; })) {
    legend.push_back({"swept up", series_colour(0), Swatch::line});
    legend.push_back({"swept down", series_colour(1), Swatch::line});
  }
  if (any([](const SweepRun& run) { return finite(run) && !run.trusted; }))
    legend.push_back(
        {"not trusted", {1.0, 1.0, 1.0, 1.0}, Swatch::marker, MarkerShape::circle, kInk});
  if (any(held)) legend.push_back({kHeldLabel, kInk, Swatch::marker, MarkerShape::triangle});
  draw_legend(cr, legend, area, avoid, style);
  cairo_restore(cr);
  draw_frame(cr, tr, ax, ay, style);
  draw_title(cr, in.layout.title_anchor,
             in.spec.title.empty() ? "The largest Lyapunov exponent" : in.spec.title, style);
}

}  // namespace vibro::render
