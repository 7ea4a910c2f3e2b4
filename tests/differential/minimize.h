// Greedy shrinking of a failing scene to a small one that fails the same way, for the scan
// (RapidCheck shrinks the property tests' scenes itself). Besides what RapidCheck's shrinking
// does (fewer pellets and limiters, no forcing, no friction) it rounds every number to as few
// digits as keep the failure, so the scene can be read.
#pragma once

#include "tests/differential/checks.h"

namespace vibro::differential {

// The smallest scene reached from `scene` by simplifications under which `reproduces(·,
// finding)` holds, trying at most `attempts` candidates.
RandomScene minimize(const RandomScene& scene, const Finding& finding, int attempts = 400);

}  // namespace vibro::differential
