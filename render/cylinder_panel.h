// The 3-D panel: a pellet's trajectory on the phase cylinder, drawn by render/gl (OSMesa) into
// an image and composited into the figure's cell, with the title and the height scale in cairo.
#pragma once

#include <cairo.h>

#include <optional>
#include <string>

#include "render/panel.h"

namespace vibro::render {

// Draws the panel into an image surface; returns why it could not (OSMesa missing, or a build
// without 3-D).
std::optional<std::string> draw_cylinder_panel(cairo_t* cr, const PanelInput& in);

}  // namespace vibro::render
