#include "render/colour_bar.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "render/text.h"
#include "render/ticks.h"

namespace vibro::render {
namespace {

// RdYlBu's eleven classes, from the negative end to the positive one.
constexpr Colour kStops[] = {rgb(0x313695), rgb(0x4575b4), rgb(0x74add1), rgb(0xabd9e9),
                             rgb(0xe0f3f8), rgb(0xffffbf), rgb(0xfee090), rgb(0xfdae61),
                             rgb(0xf46d43), rgb(0xd73027), rgb(0xa50026)};
constexpr int kIntervals = static_cast<int>(std::size(kStops)) - 1;

constexpr double kTickLength = 5.0, kTickGap = 3.0, kLabelGap = 8.0;

}  // namespace

Colour DivergingScale::at(double v) const {
  const double t = std::clamp(0.5 + 0.5 * v / limit, 0.0, 1.0) * kIntervals;
  const int k = std::min(static_cast<int>(t), kIntervals - 1);
  const double f = t - k;
  const Colour& a = kStops[k];
  const Colour& b = kStops[k + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), 1.0};
}

DivergingScale diverging_scale(const std::vector<double>& values) {
  std::vector<double> magnitudes;
  for (double v : values)
    if (std::isfinite(v)) magnitudes.push_back(std::abs(v));
  if (magnitudes.empty()) return {};
  const auto kept =
      magnitudes.begin() + static_cast<long>(std::ceil(0.99 * (magnitudes.size() - 1)));
  std::nth_element(magnitudes.begin(), kept, magnitudes.end());
  if (!(*kept > 0.0)) return {};
  const double step = nice_step(*kept, 4.0);
  DivergingScale scale{std::ceil(*kept / step * (1.0 - 1e-12)) * step};
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    scale.beyond_low = scale.beyond_low || v < -scale.limit;
    scale.beyond_high = scale.beyond_high || v > scale.limit;
  }
  return scale;
}

void draw_colour_bar(cairo_t* cr, const DivergingScale& scale, const Rect& bar,
                     const std::string& label, const Style& style) {
  // A point as long as the bar is wide at an end some values lie beyond, in the end's colour.
  const double point = bar.w;
  const double top = bar.y + (scale.beyond_high ? point : 0.0);
  const double bottom = bar.bottom() - (scale.beyond_low ? point : 0.0);
  cairo_move_to(cr, bar.x, top);
  if (scale.beyond_high) cairo_line_to(cr, bar.x + 0.5 * bar.w, bar.y);
  cairo_line_to(cr, bar.right(), top);
  cairo_line_to(cr, bar.right(), bottom);
  if (scale.beyond_low) cairo_line_to(cr, bar.x + 0.5 * bar.w, bar.bottom());
  cairo_line_to(cr, bar.x, bottom);
  cairo_close_path(cr);
  // The scale's own stops in a gradient: the bar shows exactly the colours the cells take.
  cairo_pattern_t* gradient = cairo_pattern_create_linear(0.0, bottom, 0.0, top);
  cairo_pattern_set_extend(gradient, CAIRO_EXTEND_PAD);
  for (int k = 0; k <= kIntervals; ++k)
    cairo_pattern_add_color_stop_rgb(gradient, static_cast<double>(k) / kIntervals, kStops[k].r,
                                     kStops[k].g, kStops[k].b);
  cairo_set_source(cr, gradient);
  cairo_fill_preserve(cr);
  cairo_pattern_destroy(gradient);

  const double tick = style.px(kTickLength), lo = -scale.limit;
  auto y_of = [&](double v) { return bottom - (v - lo) / (2.0 * scale.limit) * (bottom - top); };
  const std::vector<Tick> ticks =
      axis_ticks({lo, scale.limit}, style.axis_room(bottom - top), false, true);
  for (const Tick& t : ticks) {
    const double y = std::floor(y_of(t.value)) + 0.5;
    cairo_move_to(cr, bar.right(), y);
    cairo_line_to(cr, bar.right() + tick, y);
  }
  set_colour(cr, kInk);
  cairo_set_line_width(cr, std::max(1.0, style.thin_width()));
  cairo_stroke(cr);

  set_font(cr, style.tick_font());
  const double labels_left = bar.right() + tick + style.px(kTickGap);
  double widest = 0.0;
  for (const Tick& t : ticks) {
    const Point at{labels_left, y_of(t.value)};
    widest = std::max(widest, text_box(cr, t.label, at, {HAlign::left, VAlign::middle}).w);
    draw_text(cr, t.label, at, {HAlign::left, VAlign::middle}, kInk);
  }
  set_font(cr, style.label_font());
  draw_text(cr, label, {labels_left + widest + style.px(kLabelGap), bar.y + 0.5 * bar.h},
            {HAlign::center, VAlign::top}, kInk, -0.5 * std::numbers::pi);
}

}  // namespace vibro::render
