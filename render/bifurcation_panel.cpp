// The bifurcation diagram: every section point of one pellet against the swept parameter, as a
// small translucent dot, so that a period-p motion reads as p dots over its value and a chaotic
// one as a dense column. Continuation swept down is told apart from swept up (hysteresis shows
// as two branches over one range), and the points of runs the trust check could not vouch for
// are drawn hollow.
#include <cmath>
#include <cstdlib>
#include <string>

#include "core/model.h"
#include "render/axes.h"
#include "render/legend.h"
#include "render/markers.h"
#include "render/panel.h"

namespace vibro::render {
namespace {

// "Ω of pellet 1 [rad/s]" for "model.pellets[0].Omega": the symbol, whose it is, and the unit.
std::string parameter_label(const std::string& path) {
  struct Name {
    const char* field;
    const char* symbol;
    const char* unit;
  };
  static const Name names[] = {
      {"F0", "F\u2080", "N"},          {"Omega", "\u03a9", "rad/s"}, {"psi", "\u03c8", "rad"},
      {"m", "m", "kg"},                {"phi0", "\u03c6\u2080", "rad"},
      {"dphi0", "\u03c6\u0307\u2080", "rad/s"},
      {"angle", "angle", "rad"},       {"k", "k", ""},              {"R", "R", "m"},
      {"g", "g", "m/s\u00b2"},         {"alpha0", "\u03b1\u2080", "rad"},
      {"k_c", "k_c", ""},              {"mu_s", "\u03bc_s", ""}};
  const std::size_t dot = path.rfind('.');
  const std::string field = path.substr(dot + 1);
  std::string whose;
  for (const char* list : {"pellets[", "limiters["}) {
    const std::size_t at = path.find(list);
    if (at == std::string::npos) continue;
    const int index = std::atoi(path.c_str() + at + std::string(list).size());
    whose = std::string(" of ") + (list[0] == 'p' ? "pellet " : "limiter ") + std::to_string(index + 1);
  }
  for (const Name& n : names)
    if (field == n.field)
      return std::string(n.symbol) + whose + (*n.unit ? std::string(" [") + n.unit + "]" : "");
  return path;
}

}  // namespace

void draw_bifurcation_panel(cairo_t* cr, const PanelInput& in) {
  const SweepResult& sweep = *in.data.sweep;
  const SweepSpec& spec = *in.data.sweep_spec;
  const Style& style = in.style;
  const int pellet = in.spec.pellet;
  const bool angle = in.spec.coordinate == SectionCoordinate::phi;
  auto coordinate = [&](const SectionPoint& p) { return angle ? wrap_angle(p.phi) : p.dphi; };

  Range x, y;
  x.include(spec.axis.from);
  x.include(spec.axis.to);
  for (const SweepRun& run : sweep.runs)
    for (const SectionPoint& p : run.points)
      if (p.pellet == pellet) y.include(coordinate(p));
  if (x.span() <= 0.0) x = {x.lo - 0.5, x.lo + 0.5};
  if (y.empty()) y = {-1.0, 1.0};
  if (y.span() <= 0.0) y = {y.lo - 0.5, y.lo + 0.5};
  const Rect& area = in.layout.plots.front();
  const bool stroboscopic = spec.section == SectionKind::stroboscopic;
  const std::string where = stroboscopic ? " at t = kT" : " before impact";
  const Axis ax = make_axis(padded(x, 0.02), area.w, false, parameter_label(spec.axis.parameter));
  const Axis ay = make_axis(padded(y, 0.05), area.h, angle,
                            std::string(angle ? "\u03c6" : "\u03c6\u0307") + where +
                                (angle ? " [rad]" : " [rad/s]"));
  const Transform tr(area, ax.range, ay.range);

  draw_grid(cr, tr, ax, ay, style);
  cairo_save(cr);
  clip_to(cr, area);
  // A dot a little over a pixel wide: dense clouds stay grey where points pile up.
  const double r = style.px(1.3);
  bool any_backward = false, any_untrusted = false;
  Obstacles avoid;
  std::vector<Point> drawn;
  for (const SweepRun& run : sweep.runs) {
    const Colour c = series_colour(run.direction < 0 ? 1 : 0);
    any_backward = any_backward || run.direction < 0;
    any_untrusted = any_untrusted || !run.trusted;
    for (const SectionPoint& p : run.points) {
      if (p.pellet != pellet) continue;
      const Point at = tr.to_pixel(run.value, coordinate(p));
      add_marker_path(cr, at, MarkerShape::circle, r);
      if (run.trusted) {
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
  if (any_backward) {
    legend.push_back({"swept up", series_colour(0), Swatch::marker});
    legend.push_back({"swept down", series_colour(1), Swatch::marker});
  }
  if (any_untrusted)
    legend.push_back({"not trusted", {1.0, 1.0, 1.0, 1.0}, Swatch::marker, MarkerShape::circle, kInk});
  draw_legend(cr, legend, area, avoid, style);
  cairo_restore(cr);
  draw_frame(cr, tr, ax, ay, style);
  const std::string title =
      in.spec.title.empty()
          ? std::string("Bifurcation diagram, ") + (stroboscopic ? "stroboscopic" : "impact") +
                " section, pellet " + std::to_string(pellet + 1)
          : in.spec.title;
  draw_title(cr, in.layout.title_anchor, title, style);
}

}  // namespace vibro::render
