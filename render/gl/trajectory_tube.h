// The trajectory as a shaded tube: a line with a round cross-section reads as depth under
// lighting, where a flat line of constant width does not.
#pragma once

#include "render/gl/cylinder_layout.h"
#include "render/gl/mesh.h"

namespace vibro::gl {

// Each branch as a closed tube of `radius` (scene units) in its palette colour, with
// outward normals and counter-clockwise front faces. A non-finite point splits its branch;
// a piece that does not move draws nothing.
Mesh trajectory_tube(const CylinderScene& scene, const HeightScale& scale, double radius);

}  // namespace vibro::gl
