#include "render/gl/cylinder_layout.h"

#include <algorithm>
#include <limits>

namespace vibro::gl {

HeightScale height_scale(const CylinderScene& scene) {
  if (scene.dphi_range && std::isfinite(scene.dphi_range->lo) &&
      std::isfinite(scene.dphi_range->hi) && scene.dphi_range->lo < scene.dphi_range->hi) {
    return {scene.dphi_range->lo, scene.dphi_range->hi};
  }
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const CylinderBranch& branch : scene.branches) {
    for (const PhasePoint& p : branch.points) {
      if (!std::isfinite(p.phi) || !std::isfinite(p.dphi)) continue;
      lo = std::min(lo, p.dphi);
      hi = std::max(hi, p.dphi);
    }
  }
  if (lo > hi) return {};
  const double span = hi - lo;
  if (span <= 1e-12 * std::max(1.0, std::abs(hi))) return {lo - 0.5, hi + 0.5};
  const double margin = 0.06 * span;
  return {lo - margin, hi + margin};
}

}  // namespace vibro::gl
