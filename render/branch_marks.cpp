#include "render/branch_marks.h"

#include <algorithm>
#include <cmath>

namespace vibro::render {
namespace {

// A speed `after` that is `before` turned over by restitution k, within 20% (and 5% of `before`,
// for a small k). Relative only: at a grazing the section's speed passes through zero with no
// jump (an impact of zero speed), and speeds of round-off size change sign there.
bool rebound(double before, double after, double k) {
  if (!(before * after < 0.0)) return false;
  return std::abs(-after - k * before) <= (0.2 * k + 0.05) * std::abs(before);
}

// The section point lies near the limiter: within 0.25 rad of its angle (mod 2π). A section just
// before or after the impact finds the pellet that close at the speeds a crossing shows.
bool near(const PhasePoint& p, const Limiter& l) {
  return std::abs(std::remainder(p.phi - l.angle, 2.0 * M_PI)) < 0.25;
}

}  // namespace

std::vector<std::size_t> section_crossings(const OrbitBranch& branch, const Model& model,
                                           int pellet) {
  std::vector<std::size_t> at;
  const auto& points = branch.points;
  for (std::size_t k = 1; k < points.size(); ++k) {
    if (pellet >= static_cast<int>(points[k].state.size()) ||
        pellet >= static_cast<int>(points[k - 1].state.size()))
      continue;
    const PhasePoint& a = points[k - 1].state[pellet];
    const PhasePoint& b = points[k].state[pellet];
    const bool crossed =
        std::any_of(model.limiters.begin(), model.limiters.end(), [&](const Limiter& l) {
          return l.k > 0.0 && l.acts_on(pellet) && near(a, l) && near(b, l) &&
                 (rebound(a.dphi, b.dphi, l.k) || rebound(b.dphi, a.dphi, l.k));
        });
    if (crossed) at.push_back(k);
  }
  return at;
}

std::vector<MarkedBifurcation> marked_bifurcations(const OrbitBranch& branch) {
  const auto& all = branch.bifurcations;
  std::vector<MarkedBifurcation> marked;
  std::vector<bool> taken(all.size(), false);
  const auto pair = [](const Bifurcation& a, const Bifurcation& b) {
    const bool kinds =
        (a.kind == BifurcationKind::fold && b.kind == BifurcationKind::period_doubling) ||
        (b.kind == BifurcationKind::fold && a.kind == BifurcationKind::period_doubling);
    return kinds && std::abs(a.value - b.value) <= 1e-5 * std::max(1.0, std::abs(a.value));
  };
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (taken[i]) continue;
    MarkedBifurcation m{all[i].kind, all[i].value, all[i].state};
    for (std::size_t j = i + 1; j < all.size(); ++j)
      if (!taken[j] && pair(all[i], all[j])) {
        taken[j] = true;
        m.kind.reset();
        break;
      }
    marked.push_back(std::move(m));
  }
  return marked;
}

}  // namespace vibro::render
