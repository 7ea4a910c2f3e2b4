// A figure's size checked against a Limits (core/run/limits.h): its print size and sides when the
// scene is read (io/scene.h, validate_scene), and the pixels too when it is drawn (render/figure.h,
// validate_figure); and the pixels a print size makes. Header-only, so that the scene reader
// checks a figure without drawing code.
#pragma once

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "core/run/limits.h"
#include "core/run/validate.h"
#include "render/plot_spec.h"

namespace vibro {

// px: a smaller side leaves no room for the axes.
inline constexpr int kMinFigureSide = 64;

// The pixels a side of `mm` makes at `dpi` dots per inch.
inline long print_pixels(double mm, double dpi) { return std::lround(mm / 25.4 * dpi); }

// Sets the figure's pixels from its print size, if it has one (check_print_size first).
inline void apply_print_size(FigureSpec& figure) {
  if (!figure.print) return;
  figure.width = static_cast<int>(print_pixels(figure.print->width_mm, figure.print->dpi));
  figure.height = static_cast<int>(print_pixels(figure.print->height_mm, figure.print->dpi));
}

// A print size's fields each within its bounds in `limits`, and the pixels they make within the
// sides and the area the pixels may have, each error naming the field of the scene's "figure"
// that changes it: a side too small names the side, too many pixels name the dpi.
inline std::optional<FieldError> check_print_size(const PrintSize& p, const Limits& limits) {
  const auto within = [](const char* field, double v, double lo, double hi,
                         const char* unit) -> std::optional<FieldError> {
    if (v >= lo && v <= hi) return std::nullopt;  // NaN fails both
    char text[96];
    std::snprintf(text, sizeof text, "must be in [%g, %g] %s", lo, hi, unit);
    return FieldError{field, text};
  };
  if (auto e =
          within("figure.width_mm", p.width_mm, limits.print_mm_min, limits.print_mm_max, "mm"))
    return e;
  if (auto e =
          within("figure.height_mm", p.height_mm, limits.print_mm_min, limits.print_mm_max, "mm"))
    return e;
  if (auto e = within("figure.font_pt", p.font_pt, limits.font_pt_min, limits.font_pt_max, "pt"))
    return e;
  if (auto e = within("figure.dpi", p.dpi, limits.dpi_min, limits.dpi_max, "dots per inch"))
    return e;
  const long w = print_pixels(p.width_mm, p.dpi), h = print_pixels(p.height_mm, p.dpi);
  char text[200];
  if (w < kMinFigureSide || h < kMinFigureSide) {
    std::snprintf(text, sizeof text,
                  "%g × %g mm at %g dpi make %ld × %ld px, less than %d px a side leaves no room "
                  "for the axes",
                  p.width_mm, p.height_mm, p.dpi, w, h, kMinFigureSide);
    return FieldError{w < kMinFigureSide ? "figure.width_mm" : "figure.height_mm", text};
  }
  if (w > limits.width || h > limits.height || w * h > limits.pixels) {
    std::snprintf(text, sizeof text,
                  "%g × %g mm at %g dpi make %ld × %ld px, more than the limit of %d × %d px "
                  "(%ld px in all): ask fewer dots per inch",
                  p.width_mm, p.height_mm, p.dpi, w, h, limits.width, limits.height, limits.pixels);
    return FieldError{"figure.dpi", text};
  }
  return std::nullopt;
}

// The print size if the figure has one (check_print_size), then width and height each in
// [kMinFigureSide, limits.width] and [.., limits.height] px.
inline std::optional<FieldError> check_figure_sides(const FigureSpec& figure,
                                                    const Limits& limits) {
  if (figure.print)
    if (auto e = check_print_size(*figure.print, limits)) return e;
  const auto side = [](const char* field, int px, int most) -> std::optional<FieldError> {
    if (px >= kMinFigureSide && px <= most) return std::nullopt;
    return FieldError{field, "must be in [" + std::to_string(kMinFigureSide) + ", " +
                                 std::to_string(most) + "] px"};
  };
  if (auto e = side("width", figure.width, limits.width)) return e;
  return side("height", figure.height, limits.height);
}

// The sides, then width × height at most limits.pixels. The default pixels allow every size the
// default sides allow: only a tightened Limits, a server's, refuses an area, hence the wording.
inline std::optional<FieldError> check_figure_size(const FigureSpec& figure, const Limits& limits) {
  if (auto e = check_figure_sides(figure, limits)) return e;
  const long pixels = static_cast<long>(figure.width) * figure.height;
  if (pixels <= limits.pixels) return std::nullopt;
  return FieldError{"width", "width × height = " + std::to_string(pixels) +
                                 " px is over the server's limit of " +
                                 std::to_string(limits.pixels) + " px"};
}

}  // namespace vibro
