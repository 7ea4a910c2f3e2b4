// The mechanism panel: the paper's Fig. 1 drawn from the scene at one instant of the run.
#pragma once

#include <cairo.h>

#include "render/panel.h"

namespace vibro::render {

// The panel's frame: metres in the circle's plane (origin at its centre, y up) to pixels in the
// plot area, with equal scales on both axes and the square of side 2·1.7·R centred in the area.
// A pellet at φ is at (R sin φ, −R cos φ).
Transform mechanism_frame(const Rect& area, double R);

// The circle of radius R to scale with its centre, the vertical and gravity, φ = 0 at the lowest
// point and the direction of +φ, the limiters as radial stops (mobile ones hollow and dashed), the
// pellets where the run had them at `spec.t` in their series colours, and the force on each forced
// pellet at that time as a tangential arrow as long as |F| is large, with its value in N; a
// scale bar in m. The run must have recorded every pellet up to spec.t.
void draw_mechanism_panel(cairo_t* cr, const PanelInput<MechanismPlot>& in);

}  // namespace vibro::render
