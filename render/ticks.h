// Tick locators (ImPlot's "nice number" locator): major ticks at 1, 2 or 5 × 10ⁿ about one per
// 100 px, and on angle axes multiples of π/4 labelled "π/4", "3π/2", "−π", ...
#pragma once

#include <string>
#include <vector>

#include "render/geometry.h"

namespace vibro::render {

struct Tick {
  double value = 0.0;
  std::string label;  // UTF-8; negative numbers use the minus sign U+2212
};

// The 1-2-5 × 10ⁿ step nearest to span / intervals.
double nice_step(double span, double intervals);

// Ticks at multiples of a nice step inside `r`, about one per `spacing_px` on an axis of
// `length_px` pixels (at least two intervals), and at least three while they stay `min_gap_px`
// apart: a small plot must not read "0" alone.
std::vector<Tick> nice_ticks(Range r, double length_px, double spacing_px = 100.0,
                             double min_gap_px = 35.0);

// Ticks at multiples of π/4, π/2, π or 2π (the smallest step at least `min_spacing_px` apart).
// Empty when they would not read better than nice ticks: fewer than three in range, or the
// range needs steps above 2π.
std::vector<Tick> angle_ticks(Range r, double length_px, double min_spacing_px = 55.0);

// Angle ticks where they read well on an angle axis, nice ticks otherwise. A vertical axis's
// labels need only their height between them, a horizontal one's their width.
std::vector<Tick> axis_ticks(Range r, double length_px, bool angle_axis, bool vertical = false);

// "0", "π/4", "−3π/2", "2π": the label of quarters·π/4.
std::string pi_label(long quarters);

// A value formatted with as many decimals as the step needs, "−" for negatives, "0" for ±0.
std::string format_tick(double value, double step);

}  // namespace vibro::render
