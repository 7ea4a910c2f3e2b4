// Primitives of a sketch drawn to scale (the mechanism panel): points moved along a direction,
// arrows with filled heads, and labels set beside what they name, clear of each other. Pixels,
// y downward; directions are unit vectors.
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "render/geometry.h"
#include "render/style.h"
#include "render/text.h"

namespace vibro::render {

inline Point along(Point from, Point direction, double distance) {
  return {from.x + distance * direction.x, from.y + distance * direction.y};
}

// The anchor of a label placed at a point in `direction` from what it names, so that the text
// extends away from it (to the right of a point it is right of, below one it is below, ...).
TextAlign facing(Point direction);

// A filled arrow head `length` px long with its tip at `tip`, pointing along `direction`.
void fill_arrow_head(cairo_t* cr, Point tip, Point direction, double length, Colour colour);

// A straight arrow from `from` to `to`: a shaft `width` px wide ending in a head `head` px long
// (shorter on an arrow shorter than its head). Nothing when the two points coincide.
void draw_arrow(cairo_t* cr, Point from, Point to, double width, double head, Colour colour);

// Where a label may go: its anchor and which way the text extends from it.
struct LabelSpot {
  Point at;
  TextAlign align;
};

// Labels on backdrops that keep clear of each other and of marks (pellets, say): each is drawn at
// the first of its spots where its box overlaps nothing placed before, or at the first spot when
// every one does (a label is never dropped).
class LabelPlacer {
 public:
  explicit LabelPlacer(const Style& style) : style_(style) {}

  void avoid(const Rect& box) { taken_.push_back(box); }
  // A straight stroke (an arrow, a stop) as a row of squares `half_width` px from its axis.
  void avoid_line(Point from, Point to, double half_width);
  // Draws in the current font.
  void place(cairo_t* cr, const std::string& text, const std::vector<LabelSpot>& spots,
             Colour colour);

 private:
  const Style& style_;
  std::vector<Rect> taken_;
};

}  // namespace vibro::render
