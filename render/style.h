// The look of a figure: colours (colour-blind safe), line widths and font sizes, scaled with the
// figure so that a larger image is the same figure drawn bigger, or to the text size a print size
// asks.
#pragma once

#include <cstddef>
#include <iterator>

#include "render/plot_spec.h"

namespace vibro::render {

struct Colour {
  double r = 0.0, g = 0.0, b = 0.0, a = 1.0;
};

constexpr Colour rgb(unsigned hex, double alpha = 1.0) {
  return {((hex >> 16) & 0xff) / 255.0, ((hex >> 8) & 0xff) / 255.0, (hex & 0xff) / 255.0, alpha};
}

// Okabe–Ito without its yellow (too faint on white) and black (kept for guides), in the order
// render/gl colours the branches of the 3-D panel, so that branch n has one colour everywhere.
inline constexpr Colour kSeriesColours[] = {rgb(0x0072B2), rgb(0xD55E00), rgb(0x009E73),
                                            rgb(0xCC79A7), rgb(0xE69F00), rgb(0x56B4E9)};
inline constexpr std::size_t kSeriesColourCount = std::size(kSeriesColours);

// The colour of series (branch, pellet) number i, counting from 0, cycling through the palette.
constexpr Colour series_colour(std::size_t i) { return kSeriesColours[i % kSeriesColourCount]; }

inline constexpr Colour kInk = rgb(0x222222);       // frame, text
inline constexpr Colour kMutedInk = rgb(0x555555);  // limiter lines and labels
inline constexpr Colour kGuide = rgb(0xBBBBBB);     // zero line, velocity jumps
inline constexpr Colour kGrid = rgb(0xEBEBEB);      // grid lines
inline constexpr Colour kFrictionZone = rgb(0xDDDDDD, 0.55);
inline constexpr Colour kOverlay = rgb(0x000000);  // first-integral curve
inline constexpr Colour kWhite = rgb(0xFFFFFF);    // open markers

inline constexpr const char* kFontFamily = "DejaVu Sans";

struct Style {
  double scale = 1.0;  // 1 for a figure of about 1200×800
  // Text sized for print (a figure's print size): axes space their ticks by the size of their
  // labels. Otherwise by pixels, as the pixel sizes were designed with.
  bool for_print = false;

  // The length an axis of `px` pixels offers its tick labels, in pixels at scale 1.
  double axis_room(double px) const { return for_print ? px / scale : px; }

  double px(double v) const { return v * scale; }
  double tick_font() const { return px(13.0); }
  double label_font() const { return px(15.0); }
  double title_font() const { return px(16.0); }
  double note_font() const { return px(12.0); }  // branch numbers, limiter labels, legend
  double curve_width() const { return px(1.5); }
  double thin_width() const { return px(1.0); }
};

// The style for a figure of width × height pixels.
Style style_for(int width, int height);

// The style of a figure: with a print size, tick labels of its font_pt at its dpi (the rest in
// proportion); without, the style for its pixels.
Style style_for(const FigureSpec& figure);

}  // namespace vibro::render
