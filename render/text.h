// Text with the cairo "toy" API in DejaVu Sans (no pango): anchored placement and measuring.
// An SVG figure keeps its labels as text: they are collected here instead of drawn (cairo's SVG
// surface would write glyph outlines) and written as <text> elements (render/svg_text.h).
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "render/geometry.h"
#include "render/style.h"

namespace vibro::render {

enum class HAlign { left, center, right };
enum class VAlign { top, middle, baseline, bottom };

struct TextAlign {
  HAlign h = HAlign::left;
  VAlign v = VAlign::baseline;
};

void set_font(cairo_t* cr, double size_px);

// The box the text occupies (font ascent to descent, advance width) when drawn at `at`.
// Uses the current font.
Rect text_box(cairo_t* cr, const std::string& text, Point at, TextAlign align);

// Draws text anchored at `at` in the current font, rotated by `angle` radians about the anchor
// (−π/2 reads bottom to top).
void draw_text(cairo_t* cr, const std::string& text, Point at, TextAlign align, Colour colour,
               double angle = 0.0);

// Draws text over a translucent white box `pad_px` larger than it, so that it stays readable
// over grid and guide lines. A box, not an outline halo: in SVG the text then stays one <text>
// element.
void draw_text_on_backdrop(cairo_t* cr, const std::string& text, Point at, TextAlign align,
                           Colour colour, double pad_px);

void set_colour(cairo_t* cr, Colour c);

// A label as it was to be drawn: in device units, anchored at `at` (the horizontal anchor at
// at.x, the baseline at at.y + baseline), rotated by `angle` about `at`.
struct PlacedText {
  std::string text;
  Point at;
  double baseline = 0.0;
  HAlign h = HAlign::left;
  double size_px = 12.0;
  Colour colour;
  double angle = 0.0;
};

// While a sink is set on cr, draw_text records into it instead of drawing; null unsets it.
void collect_text(cairo_t* cr, std::vector<PlacedText>* sink);

}  // namespace vibro::render
