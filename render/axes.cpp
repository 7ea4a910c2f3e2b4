#include "render/axes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/text.h"

namespace vibro::render {
namespace {

constexpr double kTickLength = 5.0, kTickGap = 3.0, kLabelGap = 5.0;

// Pixel coordinates of lines are snapped to half pixels so that 1-px lines stay crisp.
double crisp(double v) { return std::floor(v) + 0.5; }

}  // namespace

Range with_zero_if_near(Range speeds) {
  if (speeds.empty()) return speeds;
  const double gap = speeds.lo > 0.0 ? speeds.lo : speeds.hi < 0.0 ? -speeds.hi : 0.0;
  if (gap <= 0.25 * speeds.span()) speeds.include(0.0);
  return speeds;
}

Axis make_axis(Range range, double length_px, bool angle, std::string label, bool vertical) {
  return {range, axis_ticks(range, length_px, angle, vertical), std::move(label), true};
}

void clip_to(cairo_t* cr, const Rect& area) {
  cairo_rectangle(cr, area.x, area.y, area.w, area.h);
  cairo_clip(cr);
}

void draw_grid(cairo_t* cr, const Transform& tr, const Axis& x, const Axis& y, const Style& style) {
  const Rect& a = tr.area();
  for (const Tick& t : x.ticks) {
    const double px = crisp(tr.px(t.value));
    cairo_move_to(cr, px, a.y);
    cairo_line_to(cr, px, a.bottom());
  }
  for (const Tick& t : y.ticks) {
    const double py = crisp(tr.py(t.value));
    cairo_move_to(cr, a.x, py);
    cairo_line_to(cr, a.right(), py);
  }
  set_colour(cr, kGrid);
  cairo_set_line_width(cr, std::max(1.0, style.thin_width()));
  cairo_stroke(cr);
}

void draw_frame(cairo_t* cr, const Transform& tr, const Axis& x, const Axis& y,
                const Style& style) {
  const Rect& a = tr.area();
  const double tick = style.px(kTickLength);
  cairo_rectangle(cr, crisp(a.x), crisp(a.y), std::round(a.w), std::round(a.h));
  for (const Tick& t : x.ticks) {
    const double px = crisp(tr.px(t.value));
    cairo_move_to(cr, px, a.bottom());
    cairo_line_to(cr, px, a.bottom() + tick);
  }
  for (const Tick& t : y.ticks) {
    const double py = crisp(tr.py(t.value));
    cairo_move_to(cr, a.x, py);
    cairo_line_to(cr, a.x - tick, py);
  }
  set_colour(cr, kInk);
  cairo_set_line_width(cr, std::max(1.0, style.thin_width()));
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_SQUARE);
  cairo_stroke(cr);

  set_font(cr, style.tick_font());
  cairo_font_extents_t fe;
  cairo_font_extents(cr, &fe);
  const double x_labels_top = a.bottom() + tick + style.px(kTickGap);
  if (x.tick_labels) {
    for (const Tick& t : x.ticks)
      draw_text(cr, t.label, {tr.px(t.value), x_labels_top}, {HAlign::center, VAlign::top}, kInk);
  }
  double widest = 0.0;
  const double y_labels_right = a.x - tick - style.px(kTickGap);
  for (const Tick& t : y.ticks) {
    const Point at{y_labels_right, tr.py(t.value)};
    widest = std::max(widest, text_box(cr, t.label, at, {HAlign::right, VAlign::middle}).w);
    draw_text(cr, t.label, at, {HAlign::right, VAlign::middle}, kInk);
  }

  set_font(cr, style.label_font());
  if (x.tick_labels && !x.label.empty()) {
    const Point at{a.x + 0.5 * a.w, x_labels_top + fe.ascent + fe.descent + style.px(kLabelGap)};
    draw_text(cr, x.label, at, {HAlign::center, VAlign::top}, kInk);
  }
  if (!y.label.empty()) {
    const Point at{y_labels_right - widest - style.px(kLabelGap + 2.0), a.y + 0.5 * a.h};
    draw_text(cr, y.label, at, {HAlign::center, VAlign::bottom}, kInk, -0.5 * std::numbers::pi);
  }
}

void draw_zero_line(cairo_t* cr, const Transform& tr, const Style& style) {
  if (!tr.y_range().contains(0.0)) return;
  const double y = crisp(tr.py(0.0));
  cairo_move_to(cr, tr.area().x, y);
  cairo_line_to(cr, tr.area().right(), y);
  set_colour(cr, kGuide);
  cairo_set_line_width(cr, style.thin_width());
  cairo_stroke(cr);
}

void draw_title(cairo_t* cr, Point top_centre, const std::string& title, const Style& style) {
  set_font(cr, style.title_font());
  draw_text(cr, title, top_centre, {HAlign::center, VAlign::top}, kInk);
}

void draw_panel_letter(cairo_t* cr, const Rect& cell, std::size_t index, const Style& style) {
  const std::string letter = "(" + std::string(1, static_cast<char>('a' + index % 26)) + ")";
  set_font(cr, style.title_font());
  draw_text(cr, letter, {cell.x + style.px(12.0), cell.y + style.px(9.0)},
            {HAlign::left, VAlign::top}, kInk);
}

}  // namespace vibro::render
