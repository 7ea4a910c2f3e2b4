// The numbers of a phase portrait's branches (the paper's motion intervals), placed beside each
// long enough branch where they hide no other number and no impact marker.
#pragma once

#include <cairo.h>

#include <vector>

#include "render/geometry.h"
#include "render/style.h"

namespace vibro::render {

struct NumberedLine {
  int index = 1;              // the number drawn, and the branch's colour
  std::vector<Point> pixels;  // the branch as drawn
  bool labelled = true;       // false: drawn without a number (a piece of a wrapped branch)
};

// Numbers each line long enough to carry one, beside its middle (or a third of the way along
// either end when the middle is taken), left of the direction of travel and then right, never
// over a box of `keep_clear` (markers) or another number, and inside `area`. Returns the boxes of
// the numbers drawn.
std::vector<Rect> draw_branch_numbers(cairo_t* cr, const std::vector<NumberedLine>& lines,
                                      const Rect& area, const Style& style,
                                      const std::vector<Rect>& keep_clear);

// The colour of branch `index` (numbered from 1), in every panel.
Colour branch_colour(int index);

}  // namespace vibro::render
