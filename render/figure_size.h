// A figure's size checked against a Limits (core/run/limits.h): the sides when the scene is read
// (io/scene.h, validate_scene), and the pixels too when it is drawn (render/figure.h,
// validate_figure). Header-only, so that the scene reader checks a figure without drawing code.
#pragma once

#include <optional>
#include <string>

#include "core/run/limits.h"
#include "core/run/validate.h"
#include "render/plot_spec.h"

namespace vibro {

// px: a smaller side leaves no room for the axes.
inline constexpr int kMinFigureSide = 64;

// Width and height each in [kMinFigureSide, limits.width] and [.., limits.height] px.
inline std::optional<FieldError> check_figure_sides(const FigureSpec& figure,
                                                    const Limits& limits) {
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
