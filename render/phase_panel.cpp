// The phase portrait (φ, φ̇) of one pellet, drawn in layers: grid, friction zones, guides,
// first-integral overlay, branches, velocity jumps and impacts, labels, frame, legend.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/model/first_integral.h"
#include "render/axes.h"
#include "render/branch_numbers.h"
#include "render/event_marks.h"
#include "render/legend.h"
#include "render/limiter_lines.h"
#include "render/panel.h"
#include "render/phase_jumps.h"
#include "render/polyline.h"
#include "render/text.h"
#include "render/track_window.h"

namespace vibro::render {
namespace {

struct VisibleBranch {
  int index = 1;
  double t = 0.0;             // s: its first sample's time in the window
  std::vector<Point> data;    // (φ, φ̇) inside the window
  std::vector<Point> pixels;  // thinned
  bool labelled = true;       // false on the shorter pieces of a branch cut by wrapping φ
};

constexpr double kPi = 0.5 * kTwoPi;

// Viridis from dark blue (0) through green to yellow (1): perceptually even, legible in grey
// and to colour-blind readers.
Colour time_colour(double u) {
  static constexpr Colour stops[] = {rgb(0x440154), rgb(0x3B528B), rgb(0x21918C), rgb(0x5EC962),
                                     rgb(0xFDE725)};
  const double x = std::clamp(u, 0.0, 1.0) * 4.0;
  const int k = std::min(static_cast<int>(x), 3);
  const double f = x - k;
  const Colour &a = stops[k], &b = stops[k + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), 1.0};
}

std::string short_time(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", t);
  return text;
}

// A branch's colour as the plot asks: its own, the first series colour, or its start's time
// over the times the branches start at.
Colour curve_colour(PhaseColours colours, const VisibleBranch& b, Range times) {
  if (colours == PhaseColours::branch) return branch_colour(b.index);
  if (colours == PhaseColours::one) return series_colour(0);
  return time_colour(times.span() > 0.0 ? (b.t - times.lo) / times.span() : 0.0);
}

// φ on one turn, [−π, π).
double on_one_turn(double phi) { return phi - kTwoPi * std::floor((phi + kPi) / kTwoPi); }

// A branch with φ on one turn, cut where it passes ±π (a line across the plot otherwise); only
// its longest piece carries the branch's number.
void wrap_into(VisibleBranch b, std::vector<VisibleBranch>& out) {
  const std::size_t first = out.size();
  VisibleBranch piece{b.index, b.t, {}, {}, true};
  for (const Point& p : b.data) {
    const Point w{on_one_turn(p.x), p.y};
    if (!piece.data.empty() && std::abs(w.x - piece.data.back().x) > kPi) {
      out.push_back(std::move(piece));
      piece = VisibleBranch{b.index, b.t, {}, {}, true};
    }
    piece.data.push_back(w);
  }
  out.push_back(std::move(piece));
  std::size_t longest = first;
  for (std::size_t k = first; k < out.size(); ++k) {
    if (out[k].data.size() > out[longest].data.size()) longest = k;
    out[k].labelled = false;
  }
  out[longest].labelled = true;
}

std::vector<VisibleBranch> visible_branches(const PelletTrack& track, const PhasePlot& spec) {
  std::vector<VisibleBranch> branches;
  for (const Branch& b : track.branches) {
    if (!branch_selected(spec, b.index)) continue;
    const auto samples = clip_to_window(b.samples, spec.t_from, spec.t_to);
    if (samples.empty()) continue;
    VisibleBranch v{b.index, samples.front().t, {}, {}, true};
    v.data.reserve(samples.size());
    for (const Sample& s : samples) v.data.push_back({s.phi, s.dphi});
    if (spec.wrap)
      wrap_into(std::move(v), branches);
    else
      branches.push_back(std::move(v));
  }
  return branches;
}

// The first-integral curves through the point: the curve of direction s carries φ̇ of sign s
// only, so a point with φ̇ ≠ 0 gets one curve and a point at rest both.
std::vector<std::vector<Point>> first_integral_curves(const Model& model, PhasePoint through,
                                                      Range phi, int samples) {
  std::vector<std::vector<Point>> curves;
  for (int s : {1, -1}) {
    if (through.dphi * s < 0.0) continue;
    const FirstIntegral fi(model, s, through.phi, through.dphi);
    std::vector<Point> curve;
    for (int i = 0; i <= samples; ++i) {
      const double x = phi.lo + phi.span() * i / samples;
      const double d2 = fi.dphi_squared(x);
      if (d2 >= 0.0 && std::isfinite(d2)) {
        curve.push_back({x, s * std::sqrt(d2)});
      } else if (!curve.empty()) {
        curves.push_back(std::move(curve));
        curve.clear();
      }
    }
    if (!curve.empty()) curves.push_back(std::move(curve));
  }
  return curves;
}

void draw_friction_zones(cairo_t* cr, const Transform& tr, double alpha0) {
  const Range& x = tr.x_range();
  const Rect& a = tr.area();
  const long first = static_cast<long>(std::ceil((x.lo - alpha0) / kTwoPi));
  const long last = static_cast<long>(std::floor((x.hi + alpha0) / kTwoPi));
  for (long n = first; n <= last && n - first < 64; ++n) {
    const double left = tr.px(n * kTwoPi - alpha0), right = tr.px(n * kTwoPi + alpha0);
    cairo_rectangle(cr, left, a.y, std::max(right - left, 1.0), a.h);
  }
  set_colour(cr, kFrictionZone);
  cairo_fill(cr);
}

std::string default_title(const PhasePlot& spec, double t_end) {
  std::string title = "Phase portrait, pellet " + std::to_string(spec.pellet + 1);
  if (!spec.branches.empty()) {
    title += spec.branches.size() == 1 ? ", motion interval " : ", motion intervals ";
    for (std::size_t k = 0; k < spec.branches.size(); ++k)
      title += (k ? ", " : "") + std::to_string(spec.branches[k]);
  }
  return title + window_suffix(spec, t_end);
}

}  // namespace

void draw_phase_panel(cairo_t* cr, const PanelInput<PhasePlot>& in) {
  const PhasePlot& spec = in.spec;
  const Style& style = in.style;
  const Rect area = in.layout.plots.front();
  const PelletTrack& track = *find_track(in.run, spec.pellet);
  auto branches = visible_branches(track, spec);
  auto jumps = velocity_jumps(track, in.run.events, spec);
  if (spec.wrap)
    for (Jump& j : jumps) j.before.x = j.after.x = on_one_turn(j.before.x);

  Range phi, dphi;
  for (const VisibleBranch& b : branches)
    for (const Point& p : b.data) phi.include(p.x), dphi.include(p.y);
  dphi = with_zero_if_near(dphi);
  if (spec.first_integral_through)
    phi.include(spec.first_integral_through->phi), dphi.include(spec.first_integral_through->dphi);
  // The scene's limits where it sets them, exactly; one whole turn when φ is wrapped.
  const Range phi_axis = spec.phi_range ? Range{spec.phi_range->lo, spec.phi_range->hi}
                         : spec.wrap    ? Range{-kPi, kPi}
                                        : padded(phi, 0.03);
  const Range dphi_axis =
      spec.dphi_range ? Range{spec.dphi_range->lo, spec.dphi_range->hi} : padded(dphi, 0.05);
  const Axis x = make_axis(phi_axis, style.axis_room(area.w), true, kPhiLabel);
  const Axis y = make_axis(dphi_axis, style.axis_room(area.h), false, kDphiLabel, true);
  const Transform tr(area, x.range, y.range);
  if (in.plot_axes)
    in.plot_axes->push_back({PlotAxesKind::phase, spec.pellet, area.x, area.y, area.w, area.h,
                             x.range.lo, x.range.hi, y.range.lo, y.range.hi});

  draw_grid(cr, tr, x, y, style);
  cairo_save(cr);
  clip_to(cr, area);
  std::vector<LegendEntry> legend;
  Obstacles avoid;
  if (spec.friction_zone && in.model.alpha0 > 0.0) {
    draw_friction_zones(cr, tr, in.model.alpha0);
    legend.push_back({"friction zone |\u03c6 \u2212 2\u03c0n| \u2264 \u03b1\u2080", kFrictionZone,
                      Swatch::area});
  }
  draw_zero_line(cr, tr, style);
  const auto limiters = limiter_lines(in.model, x.range);
  draw_limiter_lines(cr, tr, limiters, Orientation::vertical, style);

  if (spec.first_integral_through) {
    const double dash[] = {style.px(5.0), style.px(3.0)};
    cairo_set_dash(cr, dash, 2, 0.0);
    set_colour(cr, kOverlay);
    cairo_set_line_width(cr, style.thin_width());
    const int samples = std::max(400, static_cast<int>(area.w));
    for (const auto& curve :
         first_integral_curves(in.model, *spec.first_integral_through, x.range, samples)) {
      avoid.lines.push_back(to_thinned_pixels(tr, curve));
      stroke_polyline(cr, avoid.lines.back());
    }
    cairo_set_dash(cr, nullptr, 0, 0.0);
    legend.push_back({"first integral (unforced)", kOverlay, Swatch::dashed_line});
  }

  // Velocity jumps under the branches, thin and dashed: they are not motion. Clamped near the
  // area like the curves (render/phase_jumps.h): with a φ̇ range far narrower than the jumps,
  // each would be dashed along millions of pixels, and cairo's SVG and PDF surfaces work through
  // every dash.
  const double jump_dash[] = {style.px(3.0), style.px(3.0)};
  cairo_set_dash(cr, jump_dash, 2, 0.0);
  for (const VerticalLine& l : jump_lines(jumps, tr)) {
    cairo_move_to(cr, l.x, l.top);
    cairo_line_to(cr, l.x, l.bottom);
  }
  set_colour(cr, kGuide);
  cairo_set_line_width(cr, style.thin_width());
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);

  cairo_set_line_width(cr, style.curve_width());
  Range times;
  for (const VisibleBranch& b : branches) times.include(b.t);
  for (VisibleBranch& b : branches) {
    b.pixels = to_thinned_pixels(tr, b.data);
    set_colour(cr, curve_colour(spec.colours, b, times));
    stroke_polyline(cr, b.pixels);
    avoid.lines.push_back(b.pixels);
  }

  // Impact markers at the state just before each impact, one fill per kind of mark; only those
  // that show (far off the area a centre would be past cairo's fixed-point range, and wrap).
  std::vector<const EventMark*> marks_shown;
  std::vector<Rect> marker_boxes;  // numbers keep clear of them
  const double reach = style.px(5.0);
  const Rect near{area.x - reach, area.y - reach, area.w + 2 * reach, area.h + 2 * reach};
  for (EventKind kind : {EventKind::limiter, EventKind::collision, EventKind::chatter}) {
    const EventMark* mark = event_mark(kind);
    std::vector<Point> centres;
    for (const Jump& j : jumps) {
      const Point c = tr.to_pixel(j.before.x, j.before.y);
      if (j.mark == mark && near.contains(c)) centres.push_back(c);
    }
    if (centres.empty()) continue;
    for (const Point& c : centres)
      marker_boxes.push_back({c.x - reach, c.y - reach, 2 * reach, 2 * reach});
    draw_event_marks(cr, centres, *mark, style);
    marks_shown.push_back(mark);
  }

  if (spec.branch_labels && spec.colours == PhaseColours::branch) {
    std::vector<NumberedLine> lines;
    for (const VisibleBranch& b : branches) lines.push_back({b.index, b.pixels, b.labelled});
    avoid.boxes = draw_branch_numbers(cr, lines, area, style, marker_boxes);
  }
  // Off the data: the curves, the event marks and the branch numbers.
  Obstacles data{avoid.lines, avoid.boxes};
  data.boxes.insert(data.boxes.end(), marker_boxes.begin(), marker_boxes.end());
  const auto limiter_boxes =
      draw_limiter_labels(cr, tr, limiters, Orientation::vertical, style, data);
  avoid.boxes.insert(avoid.boxes.end(), limiter_boxes.begin(), limiter_boxes.end());
  cairo_restore(cr);

  draw_frame(cr, tr, x, y, style);
  draw_title(cr, in.layout.title_anchor,
             spec.title.empty() ? default_title(spec, in.run.stats.t_reached) : spec.title, style);
  for (const EventMark* mark : marks_shown) legend.push_back(legend_entry(*mark));
  if (spec.colours == PhaseColours::time && !times.empty())
    for (double t : {times.lo, times.hi})
      legend.push_back({(t == times.lo ? "from t = " : "to t = ") + short_time(t) + " s",
                        time_colour(times.span() > 0.0 ? (t - times.lo) / times.span() : 0.0)});
  // The trajectory is one series; anything else drawn makes the legend worth its space.
  if (!legend.empty()) draw_legend(cr, legend, area, avoid, style);
}

}  // namespace vibro::render
