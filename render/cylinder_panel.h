// The 3-D panel: a pellet's trajectory on the phase cylinder, drawn by render/gl (OSMesa) into
// an image and composited into the figure's cell, with the title and the height scale in cairo.
#pragma once

#include <cairo.h>

#include <optional>
#include <string>
#include <vector>

#include "render/panel.h"

namespace vibro::render {

// Draws the panel into an image surface; returns why it could not (OSMesa missing, or a build
// without 3-D).
std::optional<std::string> draw_cylinder_panel(cairo_t* cr, const PanelInput<CylinderPlot>& in);

// A label drawn over the 3-D view, anchored at a projected scene point.
struct CylinderLabel {
  std::string text;
  Point at;  // pixels in the figure
};

// The view's labels: φ at the floor rim's quarter turns, φ̇ at the axis's ends, the limiters by
// number at the top of their lines. Empty in a build without 3-D.
std::vector<CylinderLabel> cylinder_labels(const PanelInput<CylinderPlot>& in);

}  // namespace vibro::render
