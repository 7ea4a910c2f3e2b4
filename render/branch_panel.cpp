// The continued branch of a periodic motion (core/analysis/orbit_continuation.h) against its
// parameter: its state on the stroboscopic section t = kT, stable stretches solid, unstable ones
// dashed and neutral ones (a multiplier on the unit circle) dotted, each bifurcation marked and
// named. Drawn alone, or over the brute-force bifurcation
// diagram of the same scene, where the two must agree wherever the motion is stable.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "render/axes.h"
#include "render/branch_marks.h"
#include "render/legend.h"
#include "render/markers.h"
#include "render/panel.h"
#include "render/parameter_label.h"
#include "render/text.h"

namespace vibro::render {
namespace {

double branch_y(SectionCoordinate coordinate, const PhasePoint& p) {
  return coordinate == SectionCoordinate::phi ? wrap_angle(p.phi) : p.dphi;
}

struct Mark {
  const char* label;  // beside the mark
  const char* name;   // in the legend
  MarkerShape shape;
  Colour colour;
};

Mark mark_of(const std::optional<BifurcationKind>& kind) {
  if (!kind)
    return {"\u221e", "a multiplier through \u221e (a fold and a period doubling at one value)",
            MarkerShape::circle, series_colour(5)};
  switch (*kind) {
    case BifurcationKind::fold:
      return {"F", "fold", MarkerShape::diamond, series_colour(2)};
    case BifurcationKind::period_doubling:
      return {"PD", "period doubling", MarkerShape::triangle, series_colour(1)};
    case BifurcationKind::neimark_sacker:
      return {"NS", "Neimark\u2013Sacker", MarkerShape::circle, series_colour(3)};
    case BifurcationKind::grazing:
      return {"G", "grazing", MarkerShape::circle, series_colour(4)};
  }
  return {"?", "?", MarkerShape::circle, kInk};
}

std::string short_number(double x) {
  std::ostringstream s;
  s.precision(5);
  s << x;
  return s.str();
}

// A branch point's stability as drawn: stable solid, unstable dashed, neutral dotted.
enum class Stability { stable, unstable, neutral };

Stability stability_of(const BranchPoint& p) {
  return p.stable ? Stability::stable : p.neutral ? Stability::neutral : Stability::unstable;
}

void stroke_stretch(cairo_t* cr, const std::vector<Point>& line, Stability stability,
                    const Style& style) {
  const cairo_line_cap_t cap = cairo_get_line_cap(cr);
  cairo_move_to(cr, line.front().x, line.front().y);
  for (const Point& p : line) cairo_line_to(cr, p.x, p.y);
  set_colour(cr, kInk);
  const double dash[] = {style.px(6.0), style.px(4.0)}, dots[] = {style.px(1.0), style.px(3.5)};
  switch (stability) {
    case Stability::stable:
      cairo_set_line_width(cr, style.px(2.2));
      cairo_set_dash(cr, dash, 0, 0.0);
      break;
    case Stability::unstable:
      cairo_set_line_width(cr, style.px(1.6));
      cairo_set_dash(cr, dash, 2, 0.0);
      break;
    case Stability::neutral:  // round dots
      cairo_set_line_width(cr, style.px(1.8));
      cairo_set_dash(cr, dots, 2, 0.0);
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
      break;
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  cairo_set_line_cap(cr, cap);
}

// The branch's line, one path per stretch of one stability (a segment takes the stability of its
// far end), broken before each index of `breaks`, whose two ends get open circles.
void draw_branch_line(cairo_t* cr, const Transform& tr, const OrbitBranch& branch, int pellet,
                      SectionCoordinate coordinate, const std::vector<std::size_t>& breaks,
                      const Style& style, std::vector<LegendEntry>& legend, Obstacles& avoid) {
  const auto& points = branch.points;
  bool drawn[3] = {false, false, false};  // per Stability
  std::vector<Point> line, ends;
  const auto broken = [&](std::size_t k) {
    return std::find(breaks.begin(), breaks.end(), k) != breaks.end();
  };
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Point at = tr.to_pixel(points[k].value, branch_y(coordinate, points[k].state[pellet]));
    if (k > 0 && broken(k)) {
      ends.insert(ends.end(), {line.back(), at});
      line.clear();
    }
    line.push_back(at);
    const bool last = k + 1 == points.size();
    const Stability stability = stability_of(points[k]);
    if (!last && !broken(k + 1) && stability_of(points[k + 1]) == stability && k > 0) continue;
    if (line.size() >= 2) {
      drawn[static_cast<int>(stability)] = true;
      stroke_stretch(cr, line, stability, style);
      avoid.lines.push_back(line);
    }
    line = {at};
  }
  if (drawn[static_cast<int>(Stability::stable)])
    legend.push_back({"stable periodic motion", kInk, Swatch::line});
  if (drawn[static_cast<int>(Stability::unstable)])
    legend.push_back({"unstable periodic motion", kInk, Swatch::dashed_line});
  if (drawn[static_cast<int>(Stability::neutral)])
    legend.push_back(
        {"neutral periodic motion (a multiplier on the unit circle)", kInk, Swatch::dotted_line});
  if (ends.empty()) return;
  draw_markers(cr, ends, MarkerShape::circle, style.px(3.5), kWhite, kInk, style.px(1.0));
  // The legend names only what shows: a break outside the plot's window is clipped away.
  const Rect area = tr.area();
  if (std::none_of(ends.begin(), ends.end(), [&](const Point& p) { return area.contains(p); }))
    return;
  legend.push_back({"break: an impact crosses t = kT there (\u03c6\u0307 jumps; no bifurcation)",
                    kWhite, Swatch::marker, MarkerShape::circle, kInk});
}

}  // namespace

Range branch_range(const OrbitBranch& branch, int pellet, SectionCoordinate coordinate) {
  Range y;
  for (const BranchPoint& p : branch.points)
    if (pellet < static_cast<int>(p.state.size())) y.include(branch_y(coordinate, p.state[pellet]));
  return y;
}

void draw_branch_curve(cairo_t* cr, const Transform& tr, const OrbitBranch& branch,
                       const Model& model, int pellet, SectionCoordinate coordinate,
                       const Style& style, std::vector<LegendEntry>& legend, Obstacles& avoid) {
  const auto& points = branch.points;
  if (points.empty() || pellet >= static_cast<int>(points.front().state.size())) return;
  // φ is continuous where an impact crosses the section; φ̇ turns over.
  const std::vector<std::size_t> breaks = coordinate == SectionCoordinate::dphi
                                              ? section_crossings(branch, model, pellet)
                                              : std::vector<std::size_t>{};
  draw_branch_line(cr, tr, branch, pellet, coordinate, breaks, style, legend, avoid);

  set_font(cr, style.note_font());
  bool seen[5] = {false, false, false, false, false};
  std::vector<Rect> labels;
  for (const MarkedBifurcation& b : marked_bifurcations(branch)) {
    if (pellet >= static_cast<int>(b.state.size())) continue;
    const Mark m = mark_of(b.kind);
    const Point at = tr.to_pixel(b.value, branch_y(coordinate, b.state[pellet]));
    if (!tr.area().contains(at)) {  // said, not lost: the legend gives where it lies
      legend.push_back({std::string(m.label) + ": " + m.name + " at " + short_number(b.value) +
                            ", outside the plot",
                        m.colour, Swatch::marker, m.shape, kInk});
      continue;
    }
    const Point centre[] = {at};
    draw_markers(cr, centre, m.shape, style.px(5.0), m.colour, kInk, style.px(0.8));
    // Beside the mark, stepped down past the labels of bifurcations close to it.
    Point label{at.x + style.px(7.0), at.y - style.px(6.0)};
    const TextAlign align{HAlign::left, VAlign::bottom};
    for (int tries = 0; tries < 6; ++tries) {
      const Rect box = text_box(cr, m.label, label, align);
      bool clear = true;
      for (const Rect& other : labels) clear = clear && !box.overlaps(other);
      if (clear) break;
      label.y += box.h + style.px(2.0);
    }
    draw_text_on_backdrop(cr, m.label, label, align, kInk, style.px(1.5));
    labels.push_back(text_box(cr, m.label, label, align));
    avoid.boxes.push_back(labels.back());
    const int kind = b.kind ? static_cast<int>(*b.kind) : 4;
    if (!seen[kind])
      legend.push_back(
          {std::string(m.label) + ": " + m.name, m.colour, Swatch::marker, m.shape, kInk});
    seen[kind] = true;
  }
}

void draw_branch_panel(cairo_t* cr, const PanelInput<BranchPlot>& in, const BranchData& continued) {
  const OrbitBranch& branch = continued.branch;
  const Style& style = in.style;
  Range x;
  for (const BranchPoint& p : branch.points) x.include(p.value);
  Range y = branch_range(branch, in.spec.pellet, in.spec.coordinate);
  if (x.empty()) x = {-1.0, 1.0};
  if (x.span() <= 0.0) x = {x.lo - 0.5, x.lo + 0.5};
  if (y.empty()) y = {-1.0, 1.0};
  if (y.span() <= 0.0) y = {y.lo - 0.5, y.lo + 0.5};
  const bool angle = in.spec.coordinate == SectionCoordinate::phi;
  const Rect& area = in.layout.plots.front();
  const Axis ax = make_axis(padded(x, 0.02), style.axis_room(area.w), false,
                            parameter_label(continued.continuation.parameter));
  const Axis ay = make_axis(
      padded(y, 0.05), style.axis_room(area.h), angle,
      std::string(angle ? "\u03c6 at t = kT [rad]" : "\u03c6\u0307 at t = kT [rad/s]"), true);
  const Transform tr(area, ax.range, ay.range);
  draw_grid(cr, tr, ax, ay, style);
  cairo_save(cr);
  clip_to(cr, area);
  std::vector<LegendEntry> legend;
  Obstacles avoid;
  draw_branch_curve(cr, tr, branch, in.model, in.spec.pellet, in.spec.coordinate, style, legend,
                    avoid);
  cairo_restore(cr);
  // Unclipped: with no free corner the legend stands above the plot.
  draw_legend(cr, legend, area, avoid, style);
  draw_frame(cr, tr, ax, ay, style);
  const std::string title =
      "Periodic motion continued, pellet " + std::to_string(in.spec.pellet + 1);
  draw_title(cr, in.layout.title_anchor, in.spec.title.empty() ? title : in.spec.title, style);
}

}  // namespace vibro::render
