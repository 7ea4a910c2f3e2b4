// The basins of attraction of a sweep over initial states: each cell coloured by the attractor
// its run settles on, a legend giving each attractor's id (as in the result), period and impacts
// per period, and cells the trust check could not vouch for struck through. On a map of φ0 and φ̇0
// of one pellet, each attractor's section points are marked where they lie, with their ids.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "render/layout.h"
#include "render/legend.h"
#include "render/markers.h"
#include "render/panel.h"
#include "render/sweep_cells.h"
#include "render/text.h"

namespace vibro::render {
namespace {

// Attractors with a colour of their own: Okabe and Ito's (told apart with any colour vision);
// the others share a dark wine, and runs not periodic within their record are light grey.
constexpr int kColouredAttractors = 8;

Colour attractor_colour(int id) {
  static constexpr Colour colours[] = {rgb(0x0072b2), rgb(0xe69f00), rgb(0x009e73), rgb(0xcc79a7),
                                       rgb(0xd55e00), rgb(0x56b4e9), rgb(0xf0e442), rgb(0x444444)};
  if (id < 0) return rgb(0xbbbbbb);
  return id < kColouredAttractors ? colours[id] : rgb(0x882255);
}

std::string attractor_label(const Attractor& a) {
  if (a.at_rest) return std::to_string(a.id) + ": at rest";
  char impacts[32];
  std::snprintf(impacts, sizeof impacts, "%.3g", a.impacts_per_period);
  return std::to_string(a.id) + ": period " + std::to_string(a.period) + ", " + impacts +
         (a.impacts_per_period == 1.0 ? " impact" : " impacts") + "/period";
}

// Whether the map's axes are φ0 and φ̇0 of one pellet: the plane the attractors' section points
// lie in, so that each is marked in its basin. That pellet's index, or −1.
int phase_plane_pellet(const SweepSpec& spec) {
  if (!spec.axis2) return -1;
  const std::string& a = spec.axis.parameter;
  const std::string& b = spec.axis2->parameter;
  const std::size_t dot = a.rfind('.');
  if (dot == std::string::npos || a.substr(dot) != ".phi0" || b != a.substr(0, dot) + ".dphi0")
    return -1;
  const std::size_t open = a.find('[');
  return open == std::string::npos ? -1 : std::atoi(a.c_str() + open + 1);
}

// Each attractor's section points (the pellet's), where they fall inside the map: a white circle
// edged in ink (seen on any cell's colour), with its id beside it. Whether any was drawn.
bool mark_attractors(cairo_t* cr, const CellMap& map, const SweepResult& result, int pellet,
                     int pellets, const Style& style) {
  const Rect& area = map.tr.area();
  set_font(cr, style.note_font());
  bool marked = false;
  for (const Attractor& a : result.attractors)
    for (std::size_t k = pellet; k < a.section.size(); k += pellets) {
      const Point at = map.tr.to_pixel(a.section[k].first, a.section[k].second);
      if (!area.contains(at)) continue;
      add_marker_path(cr, at, MarkerShape::circle, style.px(5.0));
      set_colour(cr, {1.0, 1.0, 1.0, 1.0});
      cairo_fill_preserve(cr);
      set_colour(cr, kInk);
      cairo_set_line_width(cr, style.px(1.2));
      cairo_stroke(cr);
      draw_text_on_backdrop(cr, std::to_string(a.id), {at.x + style.px(8.0), at.y},
                            {HAlign::left, VAlign::middle}, kInk, style.px(2.0));
      marked = true;
    }
  return marked;
}

}  // namespace

void draw_basins_panel(cairo_t* cr, const PanelInput<SweepPlot>& in, const SweepData& sweep) {
  const CellMap map = draw_cells(
      cr, in, sweep, [](const SweepRun& run) { return attractor_colour(run.attractor); });
  // Which attractors the cells show, and whether some run is not periodic.
  std::vector<char> shown(sweep.result.attractors.size(), 0);
  bool unsettled = false;
  for (const SweepRun& run : sweep.result.runs) {
    if (!shown_in_cell(run)) continue;
    if (run.attractor < 0)
      unsettled = true;
    else if (run.attractor < static_cast<int>(shown.size()))
      shown[run.attractor] = 1;
  }
  std::vector<LegendEntry> legend;
  bool others = false;
  for (const Attractor& a : sweep.result.attractors) {
    if (!shown[a.id]) continue;
    if (a.id < kColouredAttractors)
      legend.push_back({attractor_label(a), attractor_colour(a.id), Swatch::area});
    else
      others = true;
  }
  if (others)
    legend.push_back({"other attractors", attractor_colour(kColouredAttractors), Swatch::area});
  if (unsettled) legend.push_back({"not periodic", attractor_colour(-1), Swatch::area});
  if (map.untrusted) legend.push_back({"not trusted", kInk, Swatch::line});
  if (const int pellet = phase_plane_pellet(sweep.spec);
      pellet >= 0 && pellet < in.model.size() &&
      mark_attractors(cr, map, sweep.result, pellet, in.model.size(), in.style))
    legend.push_back(
        {"attractor at t = kT", {1.0, 1.0, 1.0, 1.0}, Swatch::marker, MarkerShape::circle, kInk});
  draw_frame(cr, map.tr, map.x, map.y, in.style);
  draw_legend(cr, legend, legend_column(in), {}, in.style);
  draw_title(cr, in.layout.title_anchor,
             in.spec.title.empty() ? "Basins of attraction" : in.spec.title, in.style);
}

}  // namespace vibro::render
