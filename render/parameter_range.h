// The swept parameter's range on a sweep plot's axis: continuous (the values and a margin) on a
// bifurcation diagram or a Lyapunov plot, or in cells (each value the centre of its cell) on a
// regime or Lyapunov map.
#pragma once

#include "core/analysis/sweep.h"
#include "render/geometry.h"

namespace vibro::render {

// The sweep's values and a margin of 2 % each side; a unit span around a single value.
Range bifurcation_range(const SweepAxis& axis);

// From the first cell's edge to the last's: each value is the centre of its cell.
Range cell_range(const SweepAxis& axis);

// The index of a value on its axis (the cell it is the centre of).
int cell_index(const SweepAxis& axis, double v);

}  // namespace vibro::render
