// The period of a stroboscopic section: the smallest p for which the states at a forcing
// period's multiples repeat every p of them, within a tolerance scaled to their spread. A sweep
// reads a run's period off it (core/analysis/sweep.h), and a run that ends once its section has
// settled (SimOptions::settle_window) asks it after every stop.
#pragma once

#include <span>

#include "core/run/result.h"

namespace vibro {

// The smallest p with 2p <= K such that the states k and k + p (k = 0 … K − p, K + 1 states)
// agree, each pellet's φ (mod 2π) within 1e-5·(floor + its spread) and φ̇ within
// 1e-5·(floor·speed_scale + its spread); 0 when there is none (fewer than 3 states included).
int section_period(std::span<const StateAt> stops, double speed_scale, double floor = 1.0);

// The floor of the settle test's tolerances (section_settled), 1e-4 rad and 1e-4·speed_scale, and
// of the period test of a run that may end once settled. Such a run ends where it is within about
// that of its attractor: two runs of one attractor then agree within twice that plus 2e-5 of the
// spread, under the 1e-3 an attractor's runs are matched by (core/analysis/attractors.h), and it
// ends log(10)/log(1/|multiplier|) periods sooner than at the period test's own floor (1).
inline constexpr double kSettleFloor = 10.0;

// The gap between states p apart, in units of the period test's tolerance, below which a section
// counts as settled whatever its trend: about 1e-7 of the scale, near a tight run's round-off.
inline constexpr double kSettledGap = 1e-2;

// Whether the section has settled, the tolerances' floor kSettleFloor: it repeats with a period
// (section_period), the later half of
// it with the same period (so at most a quarter of its length), and the gaps
// between its states a period apart shrink fast enough that, going on as they do from the
// window's first half to its second (geometrically), they add up to within the period test's
// tolerance: a slowly converging motion (multipliers near the unit circle) is not taken for
// settled while its states still creep by a tolerance per period. Below kSettledGap it is.
bool section_settled(std::span<const StateAt> stops, double speed_scale);

}  // namespace vibro
