#include "render/event_marks.h"

namespace vibro::render {
namespace {

constexpr Colour kNone{0.0, 0.0, 0.0, 0.0};
constexpr EventMark kLimiterMark{MarkerShape::circle, kInk, kNone, "limiter impact"};
constexpr EventMark kCollisionMark{MarkerShape::diamond, rgb(0xFFFFFF), kInk, "collision"};
constexpr EventMark kChatterMark{MarkerShape::triangle, kInk, kNone, "chatter, rest at limiter"};

constexpr double kRadius = 3.0;

}  // namespace

const EventMark* event_mark(EventKind kind) {
  switch (kind) {
    case EventKind::limiter:
      return &kLimiterMark;
    case EventKind::collision:
      return &kCollisionMark;
    case EventKind::chatter:
      return &kChatterMark;
    default:
      return nullptr;
  }
}

LegendEntry legend_entry(const EventMark& mark) {
  return {mark.label, mark.fill, Swatch::marker, mark.shape, mark.edge};
}

void draw_event_marks(cairo_t* cr, std::span<const Point> centres, const EventMark& mark,
                      const Style& style) {
  draw_markers(cr, centres, mark.shape, style.px(kRadius), mark.fill, mark.edge,
               mark.edge.a > 0.0 ? style.thin_width() : 0.0);
}

}  // namespace vibro::render
