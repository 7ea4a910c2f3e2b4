// The work-precision diagram: log10 of the true error against log10 of the median run time,
// one line per method, so the cheapest method at each accuracy reads off at a glance.
#include <algorithm>
#include <cmath>
#include <map>

#include "render/axes.h"
#include "render/legend.h"
#include "render/markers.h"
#include "render/panel.h"
#include "render/polyline.h"
#include "render/text.h"

namespace vibro::render {
namespace {

// "10⁻⁶" for the decade k.
std::string decade_label(int k) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string exponent = k < 0 ? "⁻" : "";
  const std::string n = std::to_string(std::abs(k));
  for (char c : n) exponent += digits[c - '0'];
  return "10" + exponent;
}

// "0.2", "5", "20": a 1-2-5 tick of a log axis in plain decimals.
std::string plain_label(double value) {
  std::string s = std::to_string(value);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

// A log axis fitted to the data (a twentieth of its span, at least a tenth of a decade, beyond
// each end; whole decades would give 0.1 to 100 ms for runs of 0.35 to 12 ms): a tick at each
// decade inside it (every other one if crowded); when few decades span it, also at 2 and 5 times
// each, in plain decimals (`plain`: e.g. ms).
Axis decade_axis(Range r, double length_px, std::string label, bool plain) {
  const double pad = std::max(0.05 * (r.hi - r.lo), 0.1);
  Axis axis;
  axis.range = {r.lo - pad, r.hi + pad};
  axis.label = std::move(label);
  const int lo = static_cast<int>(std::floor(axis.range.lo));
  const int hi = static_cast<int>(std::ceil(axis.range.hi));
  const int span = std::max(hi - lo, 1);
  const int every = std::max(1, static_cast<int>(std::ceil(span * 60.0 / length_px)));
  const bool fine = plain && span * 3 * 60.0 <= length_px && lo >= -4 && hi <= 5;
  const auto tick = [&axis](double at, std::string text) {
    if (axis.range.contains(at)) axis.ticks.push_back({at, std::move(text)});
  };
  for (int k = lo; k <= hi; ++k) {
    if ((k - lo) % every != 0) continue;
    const double decade = std::pow(10.0, k);
    tick(k, fine ? plain_label(decade) : decade_label(k));
    if (!fine) continue;
    for (double m : {2.0, 5.0}) tick(k + std::log10(m), plain_label(m * decade));
  }
  return axis;
}

std::string error_label(ErrorReference r) {
  switch (r) {
    case ErrorReference::first_integral:
      return "error: first-integral residual";
    case ErrorReference::energy:
      return "error: energy drift";
    case ErrorReference::reference_run:
      return "error vs reference run";
  }
  return "error";
}

}  // namespace

void draw_work_precision_panel(cairo_t* cr, const PanelInput<WorkPrecisionPlot>& in,
                               const WorkPrecisionReport& report) {
  const Style& style = in.style;
  std::map<Method, std::vector<const WorkPrecisionPoint*>> lines;
  Range x, y;
  for (const WorkPrecisionPoint& p : report.points) {
    if (!p.completed || !(p.median_ms > 0.0) || !std::isfinite(p.error)) continue;
    lines[p.method].push_back(&p);
    x.include(std::log10(p.median_ms));
    y.include(std::log10(std::max(p.error, 1e-17)));
  }
  if (x.empty()) x = {-1.0, 1.0};
  if (y.empty()) y = {-12.0, 0.0};
  const Rect& area = in.layout.plots.front();
  const Axis ax = decade_axis(x, area.w, "median run time [ms]", true);
  const Axis ay = decade_axis(y, area.h, error_label(report.reference), false);
  const Transform tr(area, ax.range, ay.range);

  draw_grid(cr, tr, ax, ay, style);
  cairo_save(cr);
  clip_to(cr, area);
  Obstacles avoid;
  std::vector<LegendEntry> legend;
  std::size_t colour = 0;
  bool diverged = false;
  // The loosest and tightest tolerance at the ends of each line, placed once every line is drawn.
  struct EndLabel {
    Point point;
    std::string text;
    Colour colour;
  };
  std::vector<EndLabel> ends;
  const double marker = style.px(3.5);
  for (const auto& [method, points] : lines) {
    const Colour c = series_colour(colour++);
    std::vector<Point> px, odd;
    for (const WorkPrecisionPoint* p : points) {
      px.push_back(tr.to_pixel(std::log10(p->median_ms), std::log10(std::max(p->error, 1e-17))));
      if (!p->events_match) odd.push_back(px.back());
    }
    set_colour(cr, c);
    cairo_set_line_width(cr, style.curve_width());
    stroke_polyline(cr, px);
    draw_markers(cr, px, MarkerShape::circle, marker, c, c, 0.0);
    draw_markers(cr, odd, MarkerShape::diamond, style.px(6.0), {1, 1, 1, 1}, kInk, style.px(1.0));
    diverged = diverged || !odd.empty();
    for (const auto& [point, rtol] :
         {std::pair{px.front(), points.front()->rtol}, std::pair{px.back(), points.back()->rtol}})
      ends.push_back(
          {point, "rtol " + decade_label(static_cast<int>(std::lround(std::log10(rtol)))), c});
    avoid.lines.push_back(px);
    legend.push_back({std::string(method_name(method)), c, Swatch::line});
  }
  // Each end label beside its point, else above, below or before it, wherever it covers no
  // other label and no marker (radau5's and auto's rtol 1e-12 labels lay on top of each other
  // on the stiff-friction scene, and later lines' markers on earlier lines' labels on the
  // chatter scene); none where another line's label already sits (auto often runs exactly as
  // dop853 does).
  std::vector<Rect> markers;
  for (const std::vector<Point>& line : avoid.lines)
    for (const Point& q : line)
      markers.push_back({q.x - marker, q.y - marker, 2 * marker, 2 * marker});
  set_font(cr, style.note_font());
  for (const EndLabel& end : ends) {
    const double gap = style.px(6);
    const Point& point = end.point;
    const std::pair<Point, TextAlign> spots[] = {
        {{point.x + gap, point.y}, {HAlign::left, VAlign::middle}},
        {{point.x + gap, point.y - gap}, {HAlign::left, VAlign::bottom}},
        {{point.x + gap, point.y + gap}, {HAlign::left, VAlign::top}},
        {{point.x - gap, point.y}, {HAlign::right, VAlign::middle}}};
    const Rect beside = text_box(cr, end.text, spots[0].first, spots[0].second);
    const bool taken = std::any_of(avoid.boxes.begin(), avoid.boxes.end(), [&](const Rect& b) {
      return std::abs(b.x - beside.x) < style.px(12) && std::abs(b.y - beside.y) < style.px(8);
    });
    if (taken) continue;
    for (const auto& [at, align] : spots) {
      const Rect box = text_box(cr, end.text, at, align);
      const auto covers = [&](const Rect& b) { return b.overlaps(box); };
      // Inside the plot, which clips: the last point's label beside it was cut off at the frame.
      const bool inside = box.x >= area.x && box.right() <= area.right() && box.y >= area.y &&
                          box.bottom() <= area.bottom();
      if (!inside || std::any_of(avoid.boxes.begin(), avoid.boxes.end(), covers) ||
          std::any_of(markers.begin(), markers.end(), covers))
        continue;
      draw_text(cr, end.text, at, align, end.colour);
      avoid.boxes.push_back(box);
      break;
    }
  }
  if (diverged) {
    legend.push_back(
        {"events differ from the reference", kInk, Swatch::marker, MarkerShape::diamond, kInk});
  }
  draw_legend(cr, legend, area, avoid, style);
  cairo_restore(cr);
  draw_frame(cr, tr, ax, ay, style);
  draw_title(cr, in.layout.title_anchor,
             in.spec.title.empty() ? "Work-precision: error against run time" : in.spec.title,
             style);
}

}  // namespace vibro::render
