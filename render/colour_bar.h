// A diverging colour scale centred at 0, and its colour bar beside a map: ColorBrewer's RdYlBu
// (blue below 0, pale yellow at 0, red above; legible to colour-blind readers), symmetric about
// 0, so that the sign reads off the hue and equal magnitudes get equally strong colours.
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "render/geometry.h"
#include "render/style.h"

namespace vibro::render {

struct DivergingScale {
  double limit = 1.0;  // > 0: the values at the bar's ends, −limit and +limit
  bool beyond_low = false, beyond_high = false;  // some values lie beyond an end
  // The colour of v, clamped to ±limit.
  Colour at(double v) const;
};

// A scale whose ends reach all but the largest 1 % of the magnitudes of the finite `values`
// (all of them, up to 100 values), rounded up to a multiple of a 1-2-5 × 10ⁿ step: a few runs
// far beyond the rest (near a grazing impact, say) take the ends' colours instead of washing out
// every other cell, and the bar says so. ±1 for no values.
DivergingScale diverging_scale(const std::vector<double>& values);

// The bar in `bar` (px), −limit at the bottom and +limit at the top, in a frame, pointed at an
// end beyond which some values lie; ticks and their labels right of it, and `label` right of
// them, reading upward.
void draw_colour_bar(cairo_t* cr, const DivergingScale& scale, const Rect& bar,
                     const std::string& label, const Style& style);

}  // namespace vibro::render
