// Axes of a 2-D plot: light grid behind the data, then frame, outward ticks, tick labels, axis
// labels with units ("φ [rad]", "φ̇ [rad/s]", "t [s]") and the panel title.
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "render/style.h"
#include "render/ticks.h"
#include "render/transform.h"

namespace vibro::render {

struct Axis {
  Range range;
  std::vector<Tick> ticks;
  std::string label;        // with units; empty: none
  bool tick_labels = true;  // false on the upper of two stacked plots
};

// An axis over `range` drawn `length_px` long; angle axes get π/4 ticks where they read well.
// A vertical axis's ticks may stand closer (a label's height apart, not its width).
Axis make_axis(Range range, double length_px, bool angle, std::string label, bool vertical = false);

// A φ̇ range with 0 in it when the data comes near it (within a quarter of its own span): the
// line φ̇ = 0, where a pellet turns, is then on the plot; far from the data it would flatten it
// into a strip (a pellet swinging between 5.6 and 6 rad/s).
Range with_zero_if_near(Range speeds);

// The axis symbols, shared by every panel.
inline constexpr const char* kPhiLabel = "\u03c6 [rad]";
inline constexpr const char* kDphiLabel = "\u03c6\u0307 [rad/s]";  // φ with a combining dot above
inline constexpr const char* kTimeLabel = "t [s]";

void draw_grid(cairo_t* cr, const Transform& tr, const Axis& x, const Axis& y, const Style& style);
void draw_frame(cairo_t* cr, const Transform& tr, const Axis& x, const Axis& y, const Style& style);
// A light horizontal line at y = 0 when it is in range (φ̇ = 0: where the pellet reverses).
void draw_zero_line(cairo_t* cr, const Transform& tr, const Style& style);

void draw_title(cairo_t* cr, Point top_centre, const std::string& title, const Style& style);

// "(a)", "(b)", … for panel `index` of a figure of several, at the top left of its cell, as a
// journal's figures are lettered.
void draw_panel_letter(cairo_t* cr, const Rect& cell, std::size_t index, const Style& style);

// Clips drawing to the plot area (the caller resets the clip).
void clip_to(cairo_t* cr, const Rect& area);

}  // namespace vibro::render
