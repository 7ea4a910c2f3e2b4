// φ(t) of the listed pellets, one colour per pellet, with φ̇(t) in a second plot below sharing
// the time axis when asked (a jump in φ̇ at every impact would tangle a shared y axis).
#include <algorithm>

#include "render/axes.h"
#include "render/event_marks.h"
#include "render/legend.h"
#include "render/limiter_lines.h"
#include "render/panel.h"
#include "render/polyline.h"
#include "render/text.h"
#include "render/track_window.h"

namespace vibro::render {
namespace {

struct PelletSeries {
  int pellet = 0;
  std::vector<Point> phi;   // (t, φ), branches joined: φ is continuous
  std::vector<Point> dphi;  // (t, φ̇), joined: jumps show as vertical strokes
};

// The window cuts the joined curve, the gaps between branches included (a pellet at rest is
// not sampled): cut branch by branch, a window starting in a rest began at the next sample.
std::vector<PelletSeries> pellet_series(const PanelInput<TimePlot>& in,
                                        const std::vector<int>& pellets) {
  std::vector<PelletSeries> series;
  for (int pellet : pellets) {
    std::vector<Sample> joined;
    for (const Branch& b : find_track(in.run, pellet)->branches)
      joined.insert(joined.end(), b.samples.begin(), b.samples.end());
    PelletSeries s{pellet, {}, {}};
    for (const Sample& sample : clip_to_window(joined, in.spec.t_from, in.spec.t_to)) {
      s.phi.push_back({sample.t, sample.phi});
      s.dphi.push_back({sample.t, sample.dphi});
    }
    series.push_back(std::move(s));
  }
  return series;
}

std::string pellet_list(const std::vector<int>& pellets) {
  std::string list;
  for (std::size_t i = 0; i < pellets.size(); ++i)
    list += (i ? ", " : "") + std::to_string(pellets[i] + 1);
  return list;
}

std::string default_title(const TimePlot& spec, const std::vector<int>& pellets, double t_end) {
  const std::string what = spec.show_dphi ? "\u03c6(t) and \u03c6\u0307(t)" : "\u03c6(t)";
  return what + (pellets.size() == 1 ? ", pellet " : ", pellets ") + pellet_list(pellets) +
         window_suffix(spec, t_end);
}

// Marks the impacts touching the drawn pellets just above the time axis: limiter impacts and
// collisions on one row, chatter on the row above.
std::vector<const EventMark*> draw_event_row(cairo_t* cr, const Transform& tr,
                                             const PanelInput<TimePlot>& in,
                                             const std::vector<int>& pellets) {
  std::vector<const EventMark*> shown;
  const Rect& a = tr.area();
  for (EventKind kind : {EventKind::limiter, EventKind::collision, EventKind::chatter}) {
    // Chatter ends a run of impacts: on a row of its own above them, or the dots would hide it.
    const double y = a.bottom() - in.style.px(kind == EventKind::chatter ? 16.0 : 7.0);
    std::vector<Point> centres;
    for (const Event& e : in.run.events) {
      if (e.kind != kind || !in_window(e.t, in.spec)) continue;
      if (std::none_of(pellets.begin(), pellets.end(), [&](int p) { return touches(e, p); }))
        continue;
      centres.push_back({tr.px(e.t), y});
    }
    if (centres.empty()) continue;
    draw_event_marks(cr, centres, *event_mark(kind), in.style);
    shown.push_back(event_mark(kind));
  }
  return shown;
}

}  // namespace

void draw_time_panel(cairo_t* cr, const PanelInput<TimePlot>& in) {
  const TimePlot& spec = in.spec;
  const Style& style = in.style;
  const auto pellets = panel_pellets(spec, in.model.size());
  const auto series = pellet_series(in, pellets);

  Range t, phi, dphi;
  for (const PelletSeries& s : series) {
    for (const Point& p : s.phi) t.include(p.x), phi.include(p.y);
    for (const Point& p : s.dphi) dphi.include(p.y);
  }
  dphi = with_zero_if_near(dphi);
  const std::vector<Rect>& plots = in.layout.plots;
  const bool stacked = plots.size() > 1;
  // An instant (a window holding one sample) widened to an interval around it.
  const Axis x = make_axis(t.empty() ? Range{0.0, 1.0} : padded(t, 0.0),
                           style.axis_room(plots.front().w), false, kTimeLabel);

  // Upper (or only) plot: φ(t). A bottom strip is left free for the event marks.
  const Rect& top = plots.front();
  Range phi_range =
      spec.phi_range ? Range{spec.phi_range->lo, spec.phi_range->hi} : padded(phi, 0.05);
  phi_range.lo -= style.px(14.0) / top.h * phi_range.span();  // below the data, not over it
  const Axis y_phi = make_axis(phi_range, style.axis_room(top.h), true, kPhiLabel, true);
  const Transform tr_phi(top, x.range, y_phi.range);
  if (in.plot_axes)
    in.plot_axes->push_back({PlotAxesKind::time, -1, top.x, top.y, top.w, top.h, x.range.lo,
                             x.range.hi, y_phi.range.lo, y_phi.range.hi});

  Obstacles avoid;
  std::vector<LegendEntry> legend;
  draw_grid(cr, tr_phi, x, y_phi, style);
  cairo_save(cr);
  clip_to(cr, top);
  const auto limiters = limiter_lines(in.model, y_phi.range);
  draw_limiter_lines(cr, tr_phi, limiters, Orientation::horizontal, style);
  cairo_set_line_width(cr, style.curve_width());
  for (const PelletSeries& s : series) {
    avoid.lines.push_back(to_thinned_pixels(tr_phi, s.phi));
    set_colour(cr, series_colour(s.pellet));
    stroke_polyline(cr, avoid.lines.back());
    legend.push_back({"pellet " + std::to_string(s.pellet + 1), series_colour(s.pellet)});
  }
  const auto marks = draw_event_row(cr, tr_phi, in, pellets);
  avoid.boxes = draw_limiter_labels(cr, tr_phi, limiters, Orientation::horizontal, style, avoid);
  cairo_restore(cr);
  Axis x_top = x;
  x_top.tick_labels = !stacked;
  draw_frame(cr, tr_phi, x_top, y_phi, style);

  // Lower plot: φ̇(t).
  if (stacked) {
    const Rect& bottom = plots[1];
    const Axis y_dphi = make_axis(
        spec.dphi_range ? Range{spec.dphi_range->lo, spec.dphi_range->hi} : padded(dphi, 0.05),
        style.axis_room(bottom.h), false, kDphiLabel, true);
    const Transform tr_dphi(bottom, x.range, y_dphi.range);
    draw_grid(cr, tr_dphi, x, y_dphi, style);
    cairo_save(cr);
    clip_to(cr, bottom);
    draw_zero_line(cr, tr_dphi, style);
    cairo_set_line_width(cr, style.curve_width());
    for (const PelletSeries& s : series) {
      set_colour(cr, series_colour(s.pellet));
      stroke_polyline(cr, to_thinned_pixels(tr_dphi, s.dphi));
    }
    cairo_restore(cr);
    draw_frame(cr, tr_dphi, x, y_dphi, style);
  }

  draw_title(cr, in.layout.title_anchor,
             spec.title.empty() ? default_title(spec, pellets, in.run.stats.t_reached) : spec.title,
             style);
  for (const EventMark* mark : marks) legend.push_back(legend_entry(*mark));
  if (legend.size() > 1) draw_legend(cr, legend, top, avoid, style);
}

}  // namespace vibro::render
