// Limiter angles as guide lines: a limiter at θ acts at every θ + 2πn, so each copy inside the
// visible range gets a line (vertical in a phase portrait, horizontal over time).
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "core/model/model.h"
#include "render/legend.h"
#include "render/style.h"
#include "render/transform.h"

namespace vibro::render {

struct LimiterLine {
  double angle = 0.0;  // θ + 2πn, rad
  int limiter = 0;     // index in the model
  bool mobile = false;
};

std::vector<LimiterLine> limiter_lines(const Model& model, Range angles);

// Labels, longest first, to try where space is short: "limiter 1 (mobile)", "limiter 1", "1".
std::vector<std::string> limiter_label_choices(const LimiterLine& line);

enum class Orientation { vertical, horizontal };

// Strokes the lines across the plot area: solid for fixed limiters, dashed for mobile ones.
void draw_limiter_lines(cairo_t* cr, const Transform& tr, const std::vector<LimiterLine>& lines,
                        Orientation orientation, const Style& style);

// Labels each line (beside a vertical line, as near its top as the data lets it; above or below
// the right end of a horizontal one) with the longest choice that fits without crossing another
// line or label, or the data: a curve of `data.lines` or a box of `data.boxes` (markers, branch
// numbers). None when even the shortest does not. Returns the boxes of the labels drawn.
std::vector<Rect> draw_limiter_labels(cairo_t* cr, const Transform& tr,
                                      const std::vector<LimiterLine>& lines,
                                      Orientation orientation, const Style& style,
                                      const Obstacles& data = {});

}  // namespace vibro::render
