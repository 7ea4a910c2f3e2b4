// How impacts are marked, the same in every panel and legend: limiter impacts as filled dots,
// collisions as open diamonds, chatter (the pellet comes to rest at a limiter) as triangles.
// Reversals, sticks and releases are not marked: they are many and show in the curve itself.
#pragma once

#include <string>

#include "core/run/result.h"
#include "render/legend.h"
#include "render/markers.h"
#include "render/style.h"

namespace vibro::render {

struct EventMark {
  MarkerShape shape;
  Colour fill;
  Colour edge;  // transparent: no outline
  const char* label;
};

// The mark of an event kind; null for kinds that are not marked.
const EventMark* event_mark(EventKind kind);

// A legend entry that shows the mark.
LegendEntry legend_entry(const EventMark& mark);

// Draws `mark` at every centre.
void draw_event_marks(cairo_t* cr, std::span<const Point> centres, const EventMark& mark,
                      const Style& style);

}  // namespace vibro::render
