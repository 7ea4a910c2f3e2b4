#include "render/sketch.h"

#include <algorithm>
#include <cmath>

namespace vibro::render {

TextAlign facing(Point direction) {
  // Within about 20° of an axis the text is centred across it.
  constexpr double kSide = 0.35;
  const HAlign h = direction.x > kSide    ? HAlign::left
                   : direction.x < -kSide ? HAlign::right
                                          : HAlign::center;
  const VAlign v = direction.y > kSide    ? VAlign::top
                   : direction.y < -kSide ? VAlign::bottom
                                          : VAlign::middle;
  return {h, v};
}

void fill_arrow_head(cairo_t* cr, Point tip, Point direction, double length, Colour colour) {
  const Point base = along(tip, direction, -length);
  const Point across{-direction.y, direction.x};
  const double half = 0.38 * length;
  cairo_move_to(cr, tip.x, tip.y);
  cairo_line_to(cr, base.x + half * across.x, base.y + half * across.y);
  cairo_line_to(cr, base.x - half * across.x, base.y - half * across.y);
  cairo_close_path(cr);
  set_colour(cr, colour);
  cairo_fill(cr);
}

void draw_arrow(cairo_t* cr, Point from, Point to, double width, double head, Colour colour) {
  const double length = std::hypot(to.x - from.x, to.y - from.y);
  if (!(length > 0.0)) return;
  const Point direction{(to.x - from.x) / length, (to.y - from.y) / length};
  head = std::min(head, length);
  // The shaft stops inside the head, so that its square end does not blunt the tip.
  const Point shaft_end = along(to, direction, -0.7 * head);
  cairo_move_to(cr, from.x, from.y);
  cairo_line_to(cr, shaft_end.x, shaft_end.y);
  set_colour(cr, colour);
  cairo_set_line_width(cr, width);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_stroke(cr);
  fill_arrow_head(cr, to, direction, head, colour);
}

void LabelPlacer::avoid_line(Point from, Point to, double half_width) {
  const double length = std::hypot(to.x - from.x, to.y - from.y);
  const int squares = 1 + static_cast<int>(std::ceil(length / std::max(half_width, 1.0)));
  for (int k = 0; k <= squares; ++k) {
    const double w = static_cast<double>(k) / squares;
    const Point p{from.x + w * (to.x - from.x), from.y + w * (to.y - from.y)};
    taken_.push_back({p.x - half_width, p.y - half_width, 2.0 * half_width, 2.0 * half_width});
  }
}

void LabelPlacer::place(cairo_t* cr, const std::string& text, const std::vector<LabelSpot>& spots,
                        Colour colour) {
  if (spots.empty()) return;
  const double pad = style_.px(2.0);
  const LabelSpot* chosen = &spots.front();
  for (const LabelSpot& spot : spots) {
    const Rect box = text_box(cr, text, spot.at, spot.align);
    if (std::none_of(taken_.begin(), taken_.end(),
                     [&](const Rect& r) { return r.overlaps(box); })) {
      chosen = &spot;
      break;
    }
  }
  const Rect box = text_box(cr, text, chosen->at, chosen->align);
  taken_.push_back({box.x - pad, box.y - pad, box.w + 2.0 * pad, box.h + 2.0 * pad});
  draw_text_on_backdrop(cr, text, chosen->at, chosen->align, colour, pad);
}

}  // namespace vibro::render
