// The mechanism at one instant, drawn in layers: the vertical and the angle φ, the radius, the
// circle, the limiters' stops, the forces, the pellets, then the labels (clear of the pellets and
// of each other), gravity and the scale bar.
#include "render/mechanism_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "render/axes.h"
#include "render/limiter_lines.h"
#include "render/sketch.h"
#include "render/text.h"
#include "render/ticks.h"
#include "render/track_window.h"

namespace vibro::render {
namespace {

// Half the side of the frame's square, in radii: room outside the circle for the limiters'
// labels and the force arrows.
constexpr double kHalfSpan = 1.7;
// A limiter's stop spans these radii; the vertical guide reaches this far from the centre.
constexpr double kStopInner = 0.88, kStopOuter = 1.14, kGuideReach = 1.12;
constexpr double kPi = 0.5 * kTwoPi;

// Unit vectors in pixels (y down): from the centre toward φ, and along the circle toward +φ.
// φ = 0 is the lowest point and +φ turns toward the right-hand limiter (MODEL.md).
Point radial(double phi) { return {std::sin(phi), std::cos(phi)}; }
Point tangential(double phi) { return {std::cos(phi), -std::sin(phi)}; }

// A pellet's angle where the run had it at time t.
struct PelletAt {
  int pellet = 0;
  double phi = 0.0;
};

std::vector<PelletAt> pellets_at(const RunResult& run, int count, double t) {
  std::vector<PelletAt> out;
  for (int i = 0; i < count; ++i)
    if (const PelletTrack* track = find_track(run, i))
      if (const auto s = state_at(*track, t)) out.push_back({i, s->phi});
  return out;
}

// "F₁" for pellet index 0: the paper's subscripts, counting from 1.
std::string force_name(int pellet) {
  std::string name = "F";
  for (char digit : std::to_string(pellet + 1)) {
    name += "\xE2\x82";  // U+2080 + d, the subscript digit d, in UTF-8
    name += static_cast<char>(0x80 + (digit - '0'));
  }
  return name;
}

// The stop of a limiter across the circle at its angle: a dark bar for a fixed one, a hollow
// dashed one for a mobile one (it yields to the impact it takes).
void draw_stop(cairo_t* cr, Point centre, double radius, const Limiter& limiter,
               const Style& style) {
  const Point u = radial(limiter.angle), n{-u.y, u.x};
  const Point inner = along(centre, u, kStopInner * radius),
              outer = along(centre, u, kStopOuter * radius);
  const double half = style.px(4.0);
  cairo_new_path(cr);
  cairo_move_to(cr, inner.x + half * n.x, inner.y + half * n.y);
  cairo_line_to(cr, outer.x + half * n.x, outer.y + half * n.y);
  cairo_line_to(cr, outer.x - half * n.x, outer.y - half * n.y);
  cairo_line_to(cr, inner.x - half * n.x, inner.y - half * n.y);
  cairo_close_path(cr);
  set_colour(cr, limiter.mobile ? rgb(0xFFFFFF) : kMutedInk);
  cairo_fill_preserve(cr);
  const double dash[] = {style.px(3.0), style.px(2.0)};
  cairo_set_dash(cr, dash, limiter.mobile ? 2 : 0, 0.0);
  set_colour(cr, kMutedInk);
  cairo_set_line_width(cr, style.thin_width());
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

// The direction of the radius's dimension line: the candidate farthest from every limiter and
// pellet, so that it crosses none of them.
double free_direction(const Model& model, const std::vector<PelletAt>& pellets) {
  const auto apart = [](double a, double b) { return std::abs(std::remainder(a - b, kTwoPi)); };
  double best = 0.75 * kPi, best_gap = -1.0;
  for (double candidate :
       {0.75 * kPi, -0.75 * kPi, 0.5 * kPi, -0.5 * kPi, 0.625 * kPi, -0.625 * kPi}) {
    double gap = kPi;
    for (const Limiter& l : model.limiters) gap = std::min(gap, apart(candidate, l.angle));
    for (const PelletAt& p : pellets) gap = std::min(gap, apart(candidate, p.phi));
    if (gap > best_gap + 1e-9) best = candidate, best_gap = gap;
  }
  return best;
}

// Spots for a label at `distance` px from the centre toward φ, text extending away from the
// centre (or toward it, inward), then a little to either side along the circle, first toward
// +φ for lean +1, toward −φ for lean −1.
std::vector<LabelSpot> spots_toward(Point centre, double phi, double distance, bool inward,
                                    double lean = 1.0) {
  std::vector<LabelSpot> spots;
  for (double shift : {0.0, 0.12, -0.12, 0.24, -0.24}) {
    const Point u = radial(phi + lean * shift);
    spots.push_back({along(centre, u, distance), facing(inward ? Point{-u.x, -u.y} : u)});
  }
  return spots;
}

// Which way a pellet's label leans: away from the nearest other pellet, so that the numbers of
// pellets side by side keep their order.
double lean_of(const PelletAt& at, const std::vector<PelletAt>& pellets) {
  double nearest = kTwoPi, lean = 1.0;
  for (const PelletAt& other : pellets) {
    if (other.pellet == at.pellet) continue;
    const double gap = std::remainder(at.phi - other.phi, kTwoPi);
    if (std::abs(gap) < nearest) nearest = std::abs(gap), lean = gap < 0.0 ? -1.0 : 1.0;
  }
  return lean;
}

// The vertical through the centre (the paper's 0–0) with φ = 0 at its foot, and the angle's
// positive direction as an arc from it at the centre.
void draw_angle_origin(cairo_t* cr, Point centre, double radius, LabelPlacer& labels,
                       const Style& style) {
  const double dash[] = {style.px(8.0), style.px(3.0), style.px(2.0), style.px(3.0)};
  cairo_set_dash(cr, dash, 4, 0.0);
  cairo_new_path(cr);
  cairo_move_to(cr, centre.x, centre.y - kGuideReach * radius);
  cairo_line_to(cr, centre.x, centre.y + kGuideReach * radius);
  set_colour(cr, kGuide);
  cairo_set_line_width(cr, style.thin_width());
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);

  const double arc = 0.35 * radius, sweep = kPi / 4.0;
  // cairo measures angles clockwise from +x on the page; φ runs counter-clockwise from straight
  // down.
  cairo_arc_negative(cr, centre.x, centre.y, arc, 0.5 * kPi, 0.5 * kPi - sweep);
  set_colour(cr, kInk);
  cairo_set_line_width(cr, style.thin_width());
  cairo_stroke(cr);
  fill_arrow_head(cr, along(centre, radial(sweep), arc), tangential(sweep), style.px(8.0), kInk);
  set_font(cr, style.label_font());
  labels.place(cr, "\u03c6 = 0",
               {{{centre.x, centre.y + kGuideReach * radius}, {HAlign::center, VAlign::top}}},
               kInk);
  labels.place(cr, "+\u03c6", spots_toward(centre, 0.5 * sweep, arc + style.px(4.0), false), kInk);
}

// The radius as a dimension line from the centre toward φ, labelled with its length.
void draw_radius(cairo_t* cr, Point centre, double radius, double phi, double R,
                 LabelPlacer& labels, const Style& style) {
  const Point u = radial(phi);
  draw_arrow(cr, centre, along(centre, u, radius), style.thin_width(), style.px(9.0), kMutedInk);
  const Point n{-u.y, u.x};
  const Point above = n.y < 0.0 ? n : Point{-n.x, -n.y};
  const Point below{-above.x, -above.y};
  const Point middle = along(centre, u, 0.55 * radius);
  char text[48];
  std::snprintf(text, sizeof text, "R = %g m", R);
  set_font(cr, style.note_font());
  labels.place(cr, text,
               {{along(middle, above, style.px(4.0)), facing(above)},
                {along(middle, below, style.px(4.0)), facing(below)}},
               kMutedInk);
}

// Gravity at the top left of the plot, and a scale bar in metres at its bottom left.
void draw_gravity_and_scale(cairo_t* cr, const Rect& area, double px_per_m, double R,
                            const Style& style) {
  const Point top{area.x + style.px(24.0), area.y + style.px(14.0)};
  const double g_length = style.px(56.0);
  draw_arrow(cr, top, {top.x, top.y + g_length}, style.px(2.0), style.px(11.0), kInk);
  set_font(cr, style.label_font());
  draw_text(cr, "g", {top.x + style.px(8.0), top.y + 0.5 * g_length},
            {HAlign::left, VAlign::middle}, kInk);

  const double length = nice_step(R, 2.5);
  const Point left{area.x + style.px(24.0), area.bottom() - style.px(18.0)};
  const double right = left.x + length * px_per_m, tick = style.px(5.0);
  cairo_new_path(cr);
  cairo_move_to(cr, left.x, left.y - tick);
  cairo_line_to(cr, left.x, left.y);
  cairo_line_to(cr, right, left.y);
  cairo_line_to(cr, right, left.y - tick);
  set_colour(cr, kInk);
  cairo_set_line_width(cr, style.px(1.5));
  cairo_stroke(cr);
  set_font(cr, style.note_font());
  draw_text(cr, format_tick(length, length) + " m",
            {0.5 * (left.x + right), left.y - style.px(4.0)}, {HAlign::center, VAlign::bottom},
            kInk);
}

// A force at its pellet: where its arrow starts and ends, which way it points, and its label.
struct ForceArrow {
  int pellet = 0;
  Point from, to, direction;
  std::string label;  // "F₁ = 1.20 N"
};

// The force on each forced pellet at time t along the circle's tangent (+φ for F > 0), as long
// against 0.6 R as |F| is against the largest amplitude.
std::vector<ForceArrow> force_arrows(Point centre, double radius, const Model& model,
                                     const std::vector<PelletAt>& pellets, double t, double disc) {
  double largest = 0.0;
  for (const Pellet& p : model.pellets) largest = std::max(largest, std::abs(p.force.F0));
  const double step = nice_step(largest, 100.0);  // the values' last decimal
  std::vector<ForceArrow> arrows;
  for (const PelletAt& at : pellets) {
    const Forcing& force = model.pellets[at.pellet].force;
    if (!force.active()) continue;
    const double F = force.at(t);
    const Point dir = along({0.0, 0.0}, tangential(at.phi), F < 0.0 ? -1.0 : 1.0);
    const Point from = along(along(centre, radial(at.phi), radius), dir, 1.25 * disc);
    arrows.push_back({at.pellet, from, along(from, dir, 0.6 * radius * std::abs(F) / largest), dir,
                      force_name(at.pellet) + " = " + format_tick(F, step) + " N"});
  }
  return arrows;
}

}  // namespace

Transform mechanism_frame(const Rect& area, double R) {
  const double side = std::max(1.0, std::min(area.w, area.h));
  const double half = kHalfSpan * R;
  return Transform(area, {-half * area.w / side, half * area.w / side},
                   {-half * area.h / side, half * area.h / side});
}

void draw_mechanism_panel(cairo_t* cr, const PanelInput<MechanismPlot>& in) {
  const Model& model = in.model;
  const Style& style = in.style;
  const double R = model.R, t = in.spec.t;
  const Rect& area = in.layout.plots.front();
  const Transform tr = mechanism_frame(area, R);
  const double px_per_m = area.w / tr.x_range().span();
  const double radius = R * px_per_m, disc = style.px(8.0);
  const Point centre = tr.to_pixel(0.0, 0.0);
  const auto pellets = pellets_at(in.run, model.size(), t);
  const auto forces = force_arrows(centre, radius, model, pellets, t, disc);

  // Marks first, so that every label keeps clear of the pellets, the stops and the arrows.
  LabelPlacer labels(style);
  for (const PelletAt& at : pellets) {
    const Point p = along(centre, radial(at.phi), radius);
    labels.avoid({p.x - disc, p.y - disc, 2.0 * disc, 2.0 * disc});
  }
  for (const Limiter& l : model.limiters)
    labels.avoid_line(along(centre, radial(l.angle), kStopInner * radius),
                      along(centre, radial(l.angle), kStopOuter * radius), style.px(4.0));
  for (const ForceArrow& f : forces) labels.avoid_line(f.from, f.to, style.px(4.0));
  draw_angle_origin(cr, centre, radius, labels, style);
  draw_radius(cr, centre, radius, free_direction(model, pellets), R, labels, style);
  cairo_new_path(cr);
  cairo_arc(cr, centre.x, centre.y, radius, 0.0, kTwoPi);
  set_colour(cr, kInk);
  cairo_set_line_width(cr, style.px(2.0));
  cairo_stroke(cr);
  cairo_arc(cr, centre.x, centre.y, style.px(2.5), 0.0, kTwoPi);
  cairo_fill(cr);
  for (const Limiter& l : model.limiters) draw_stop(cr, centre, radius, l, style);
  for (const ForceArrow& f : forces)
    draw_arrow(cr, f.from, f.to, style.px(2.5), style.px(11.0), series_colour(f.pellet));
  for (const PelletAt& at : pellets) {
    const Point p = along(centre, radial(at.phi), radius);
    cairo_new_path(cr);
    cairo_arc(cr, p.x, p.y, disc, 0.0, kTwoPi);
    set_colour(cr, series_colour(at.pellet));
    cairo_fill_preserve(cr);
    set_colour(cr, kInk);
    cairo_set_line_width(cr, style.thin_width());
    cairo_stroke(cr);
  }

  // Pellets are numbered inside the circle, clear of the stops; forces at their arrows' tips;
  // limiters named outside the circle.
  set_font(cr, style.label_font());
  for (const PelletAt& at : pellets) {
    // Next to the pellet, or past the inner end of a stop it rests against.
    const double lean = lean_of(at, pellets);
    auto spots = spots_toward(centre, at.phi, radius - disc - style.px(4.0), true, lean);
    const auto past_stop =
        spots_toward(centre, at.phi, kStopInner * radius - style.px(7.0), true, lean);
    spots.insert(spots.end(), past_stop.begin(), past_stop.end());
    labels.place(cr, std::to_string(at.pellet + 1), spots, series_colour(at.pellet));
  }
  set_font(cr, style.note_font());
  labels.place(
      cr, "O",
      {{{centre.x - style.px(5.0), centre.y - style.px(3.0)}, {HAlign::right, VAlign::bottom}}},
      kInk);
  for (const ForceArrow& f : forces) {
    // At the arrow's tip, else beside its middle on either side.
    const Point middle =
        along(f.from, f.direction, 0.5 * std::hypot(f.to.x - f.from.x, f.to.y - f.from.y));
    const Point side{-f.direction.y, f.direction.x}, other{f.direction.y, -f.direction.x};
    labels.place(cr, f.label,
                 {{along(f.to, f.direction, style.px(5.0)), facing(f.direction)},
                  {along(middle, side, style.px(6.0)), facing(side)},
                  {along(middle, other, style.px(6.0)), facing(other)}},
                 series_colour(f.pellet));
  }
  for (int i = 0; i < static_cast<int>(model.limiters.size()); ++i) {
    const Limiter& l = model.limiters[i];
    labels.place(cr, limiter_label_choices({l.angle, i, l.mobile}).front(),
                 spots_toward(centre, l.angle, kStopOuter * radius + style.px(7.0), false),
                 kMutedInk);
  }
  draw_gravity_and_scale(cr, area, px_per_m, R, style);

  char title[64];
  std::snprintf(title, sizeof title, "Mechanism at t = %g s", t);
  draw_title(cr, in.layout.title_anchor, in.spec.title.empty() ? title : in.spec.title, style);
}

}  // namespace vibro::render
