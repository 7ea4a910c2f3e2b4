#include "render/legend.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/text.h"

namespace vibro::render {
namespace {

constexpr double kPadding = 7.0, kSwatchWidth = 24.0, kSwatchGap = 7.0, kRowHeight = 1.45;

void draw_swatch(cairo_t* cr, const LegendEntry& e, Point left_middle, const Style& style) {
  const double w = style.px(kSwatchWidth);
  if (e.swatch == Swatch::area) {
    const double h = 0.8 * style.note_font();
    cairo_rectangle(cr, left_middle.x, left_middle.y - 0.5 * h, w, h);
    set_colour(cr, e.colour);
    cairo_fill_preserve(cr);
    if (e.edge.a > 0.0) {  // a white area shows on the legend's white
      set_colour(cr, e.edge);
      cairo_set_line_width(cr, style.thin_width());
      cairo_stroke_preserve(cr);
    }
    cairo_new_path(cr);
    return;
  }
  if (e.swatch == Swatch::marker) {
    const Point centre{left_middle.x + 0.5 * w, left_middle.y};
    draw_markers(cr, {&centre, 1}, e.marker, style.px(3.0), e.colour, e.edge,
                 e.edge.a > 0.0 ? style.thin_width() : 0.0);
    return;
  }
  cairo_move_to(cr, left_middle.x, left_middle.y);
  cairo_line_to(cr, left_middle.x + w, left_middle.y);
  set_colour(cr, e.colour);
  cairo_set_line_width(cr, style.curve_width());
  if (e.swatch == Swatch::dashed_line) {
    const double dash[] = {style.px(5.0), style.px(3.0)};
    cairo_set_dash(cr, dash, 2, 0.0);
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

// What a legend box hides: a label costs more than any length of curve. Zero: nothing.
double placement_cost(const Rect& box, const Obstacles& avoid) {
  double cost = 0.0;
  for (const Rect& b : avoid.boxes) cost += box.overlaps(b) ? 1e9 : 0.0;
  for (const auto& line : avoid.lines) cost += length_inside(box, line);
  return cost;
}

const cairo_user_data_key_t kFitKey{};
const cairo_user_data_key_t kPlaceKey{};
// Stable addresses for the places, kept as cairo user data.
const LegendPlace kPlaces[] = {LegendPlace::inside, LegendPlace::beside, LegendPlace::above};

}  // namespace

double length_inside(const Rect& box, std::span<const Point> line) {
  double inside = 0.0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    // Liang–Barsky: the parameter interval [t0, t1] of the segment inside the box.
    const Point a = line[i - 1], b = line[i];
    const double dx = b.x - a.x, dy = b.y - a.y;
    double t0 = 0.0, t1 = 1.0;
    const double p[] = {-dx, dx, -dy, dy};
    const double q[] = {a.x - box.x, box.right() - a.x, a.y - box.y, box.bottom() - a.y};
    bool outside = false;
    for (int k = 0; k < 4 && !outside; ++k) {
      if (p[k] == 0.0) {
        outside = q[k] < 0.0;
        continue;
      }
      const double t = q[k] / p[k];
      if (p[k] < 0.0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
      outside = t0 > t1;
    }
    if (!outside) inside += (t1 - t0) * std::sqrt(dx * dx + dy * dy);  // pixels: no overflow
  }
  return inside;
}

Rect legend_box(Point size, const Rect& area, const Obstacles& avoid, double inset) {
  // Corners first, then the middles of the edges, then the centre.
  const double xs[] = {area.right() - inset - size.x, area.x + inset,
                       area.x + 0.5 * (area.w - size.x)};
  const double ys[] = {area.y + inset, area.bottom() - inset - size.y,
                       area.y + 0.5 * (area.h - size.y)};
  const int order[][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0}, {2, 1}, {0, 2}, {1, 2}, {2, 2}};
  Rect best{xs[0], ys[0], size.x, size.y};
  double least = std::numeric_limits<double>::infinity();
  for (const auto& [i, j] : order) {
    const Rect c{xs[i], ys[j], size.x, size.y};
    const double cost = placement_cost(c, avoid);
    if (cost < least) least = cost, best = c;
  }
  return best;
}

Point legend_size(cairo_t* cr, const std::vector<LegendEntry>& entries, const Style& style) {
  if (entries.empty()) return {};
  set_font(cr, style.note_font());
  double widest = 0.0;
  for (const LegendEntry& e : entries) widest = std::max(widest, text_box(cr, e.label, {}, {}).w);
  const double pad = style.px(kPadding), row = kRowHeight * style.note_font();
  return {2.0 * pad + style.px(kSwatchWidth + kSwatchGap) + widest,
          2.0 * pad + row * entries.size() - (row - style.note_font())};
}

void watch_legends(cairo_t* cr, LegendFit* fit) { cairo_set_user_data(cr, &kFitKey, fit, nullptr); }

void place_legends(cairo_t* cr, LegendPlace place) {
  cairo_set_user_data(cr, &kPlaceKey, const_cast<LegendPlace*>(&kPlaces[static_cast<int>(place)]),
                      nullptr);
}

void draw_legend(cairo_t* cr, const std::vector<LegendEntry>& entries, const Rect& area,
                 const Obstacles& avoid, const Style& style) {
  if (entries.empty()) return;
  const Point size = legend_size(cr, entries, style);
  const auto* set = static_cast<const LegendPlace*>(cairo_get_user_data(cr, &kPlaceKey));
  const LegendPlace place = set ? *set : LegendPlace::inside;
  const double inset = style.px(kLegendInset);
  const Rect box = place == LegendPlace::beside ? Rect{area.right() + inset, area.y, size.x, size.y}
                   : place == LegendPlace::above
                       ? Rect{area.right() - size.x, area.y - inset - size.y, size.x, size.y}
                       : legend_box(size, area, avoid, inset);
  if (auto* fit = static_cast<LegendFit*>(cairo_get_user_data(cr, &kFitKey))) {
    fit->hid_data =
        fit->hid_data || (place == LegendPlace::inside && placement_cost(box, avoid) > 0.0);
    fit->size = {std::max(fit->size.x, size.x), std::max(fit->size.y, size.y)};
  }
  const double pad = style.px(kPadding), row = kRowHeight * style.note_font();

  cairo_rectangle(cr, box.x, box.y, box.w, box.h);
  set_colour(cr, rgb(0xFFFFFF, 0.88));
  cairo_fill_preserve(cr);
  set_colour(cr, kGuide);
  cairo_set_line_width(cr, style.thin_width());
  cairo_stroke(cr);

  double y = box.y + pad + 0.5 * style.note_font();
  for (const LegendEntry& e : entries) {
    draw_swatch(cr, e, {box.x + pad, y}, style);
    draw_text(cr, e.label, {box.x + pad + style.px(kSwatchWidth + kSwatchGap), y},
              {HAlign::left, VAlign::middle}, kInk);
    y += row;
  }
}

}  // namespace vibro::render
