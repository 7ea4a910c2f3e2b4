// What the branch plot reads off a continued branch before drawing it: where its section state
// jumps because an impact crosses the section time (not a bifurcation: the line is broken there),
// and its bifurcations as marked, a fold and a period doubling at one value taken as one mark (a
// Floquet multiplier passing through infinity: the determinant tests of both change sign, and
// neither bifurcation happens).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/analysis/orbit_continuation.h"
#include "core/model/model.h"

namespace vibro::render {

// The indices k where φ̇ of `pellet` jumps from point k−1 to k because an impact crossed the
// section time between them: both lie near one limiter acting on the pellet, and φ̇ turns over
// with the limiter's restitution (−k φ̇ either way, to 20 % and 5 % of φ̇): not where φ̇ passes
// through zero at a grazing. Empty for a limiter with k = 0.
std::vector<std::size_t> section_crossings(const OrbitBranch& branch, const Model& model,
                                           int pellet);

// A bifurcation as the plot marks it: its kind, or none for a multiplier through infinity.
struct MarkedBifurcation {
  std::optional<BifurcationKind> kind;  // empty: a fold and a period doubling at one value
  double value = 0.0;
  std::vector<PhasePoint> state;
};

// The branch's bifurcations, each fold merged with a period doubling within 1e-5 (relative) of
// its value.
std::vector<MarkedBifurcation> marked_bifurcations(const OrbitBranch& branch);

}  // namespace vibro::render
