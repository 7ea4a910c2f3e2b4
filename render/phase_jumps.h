// The impacts a phase portrait marks: where φ̇ jumps at one φ. Limiter impacts and collisions
// show as jumps between consecutive branches; a chatter sequence summed to rest at a limiter
// shows as a jump from the speed its summation started from to rest, at the limiter (no branch
// ends there: the last ones before it are too short to see).
#pragma once

#include <span>
#include <vector>

#include "core/run/result.h"
#include "render/event_marks.h"
#include "render/geometry.h"
#include "render/plot_spec.h"
#include "render/transform.h"

namespace vibro::render {

// An impact seen in the portrait: φ̇ jumps from `before` to `after` at one φ.
struct Jump {
  Point before, after;
  const EventMark* mark;  // null: no impact listed at its time (the run kept no events there)
};

// The jumps of one pellet's track inside the plot's window and branch selection.
std::vector<Jump> velocity_jumps(const PelletTrack& track, std::span<const Event> events,
                                 const PhasePlot& spec);

// A vertical segment in pixels, from y `top` down to `bottom` at `x`.
struct VerticalLine {
  double x, top, bottom;
};

// The lines that draw the jumps, in pixels (clamped near the plot: render/polyline.h): the jumps
// in one quarter-pixel column merged where they overlap. Impacts at a limiter all jump at its
// angle, and cairo strokes thousands of overlapping lines in a time that grows with the square
// of their number (20 000 impacts took seconds); their union looks the same.
std::vector<VerticalLine> jump_lines(std::span<const Jump> jumps, const Transform& tr);

}  // namespace vibro::render
