#include "render/parameter_range.h"

#include <cmath>

namespace vibro::render {

Range bifurcation_range(const SweepAxis& axis) {
  Range x{axis.from, axis.to};
  if (x.span() <= 0.0) x = {x.lo - 0.5, x.lo + 0.5};
  return padded(x, 0.02);
}

Range cell_range(const SweepAxis& axis) {
  const double half = axis.count > 1 ? 0.5 * (axis.to - axis.from) / (axis.count - 1) : 0.5;
  return Range{axis.from - half, axis.to + half};
}

int cell_index(const SweepAxis& axis, double v) {
  return axis.count > 1 && axis.to > axis.from
             ? static_cast<int>(
                   std::lround((v - axis.from) / (axis.to - axis.from) * (axis.count - 1)))
             : 0;
}

}  // namespace vibro::render
