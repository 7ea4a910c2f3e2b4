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
  const cairo_line_cap_t cap = cairo_get_line_cap(cr);
  if (e.swatch == Swatch::dotted_line) {  // round dots
    const double dots[] = {style.px(1.0), style.px(3.0)};
    cairo_set_dash(cr, dots, 2, 0.0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  cairo_set_line_cap(cr, cap);
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

LegendGrid legend_grid(cairo_t* cr, const std::vector<LegendEntry>& entries, const Style& style,
                       double width) {
  if (entries.empty()) return {};
  set_font(cr, style.note_font());
  const double pad = style.px(kPadding), row = kRowHeight * style.note_font();
  const double swatch = style.px(kSwatchWidth + kSwatchGap), gap = 2.0 * pad;
  std::vector<double> widths;
  double widest = 0.0;
  for (const LegendEntry& e : entries) {
    widths.push_back(swatch + text_box(cr, e.label, {}, {}).w);
    widest = std::max(widest, widths.back());
  }
  // One column, or rows filled left to right as far as the width allows (at least one entry a
  // row).
  LegendGrid grid;
  double x = 0.0, right = 0.0;
  int line = 0;
  for (double w : widths) {
    if (width <= 0.0 || (x > 0.0 && pad + x + w + pad > width)) {
      if (!grid.at.empty()) ++line;
      x = 0.0;
    }
    grid.at.push_back({pad + x, pad + 0.5 * style.note_font() + line * row});
    right = std::max(right, x + (width > 0.0 ? w : widest));
    x += w + gap;
  }
  grid.size = {2.0 * pad + right, 2.0 * pad + row * (line + 1) - (row - style.note_font())};
  return grid;
}

Point legend_size(cairo_t* cr, const std::vector<LegendEntry>& entries, const Style& style) {
  return legend_grid(cr, entries, style, 0.0).size;
}

void watch_legends(cairo_t* cr, LegendFit* fit) { cairo_set_user_data(cr, &kFitKey, fit, nullptr); }

void place_legends(cairo_t* cr, LegendPlace place) {
  cairo_set_user_data(cr, &kPlaceKey, const_cast<LegendPlace*>(&kPlaces[static_cast<int>(place)]),
                      nullptr);
}

void draw_legend(cairo_t* cr, const std::vector<LegendEntry>& entries, const Rect& area,
                 const Obstacles& avoid, const Style& style) {
  if (entries.empty()) return;
  const auto* set = static_cast<const LegendPlace*>(cairo_get_user_data(cr, &kPlaceKey));
  const LegendPlace place = set ? *set : LegendPlace::inside;
  // Above the plot, the entries in as many columns as its width holds: a strip, not a tower.
  const LegendGrid strip = legend_grid(cr, entries, style, area.w);
  const LegendGrid grid =
      place == LegendPlace::above ? strip : legend_grid(cr, entries, style, 0.0);
  const Point size = grid.size;
  const double inset = style.px(kLegendInset);
  const Rect box = place == LegendPlace::beside ? Rect{area.right() + inset, area.y, size.x, size.y}
                   : place == LegendPlace::above
                       ? Rect{area.right() - size.x, area.y - inset - size.y, size.x, size.y}
                       : legend_box(size, area, avoid, inset);
  if (auto* fit = static_cast<LegendFit*>(cairo_get_user_data(cr, &kFitKey))) {
    fit->hid_data =
        fit->hid_data || (place == LegendPlace::inside && placement_cost(box, avoid) > 0.0);
    fit->size = {std::max(fit->size.x, size.x), std::max(fit->size.y, size.y)};
    fit->strip = {std::max(fit->strip.x, strip.size.x), std::max(fit->strip.y, strip.size.y)};
  }

  cairo_rectangle(cr, box.x, box.y, box.w, box.h);
  set_colour(cr, rgb(0xFFFFFF, 0.88));
  cairo_fill_preserve(cr);
  set_colour(cr, kGuide);
  cairo_set_line_width(cr, style.thin_width());
  cairo_stroke(cr);

  for (std::size_t k = 0; k < entries.size(); ++k) {
    const LegendEntry& e = entries[k];
    const double x = box.x + grid.at[k].x, y = box.y + grid.at[k].y;
    draw_swatch(cr, e, {x, y}, style);
    draw_text(cr, e.label, {x + style.px(kSwatchWidth + kSwatchGap), y},
              {HAlign::left, VAlign::middle}, kInk);
  }
}

}  // namespace vibro::render
