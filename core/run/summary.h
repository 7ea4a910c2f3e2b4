// The summary of a run (MODEL.md, "What a run must answer"), built in one pass over its events.
#pragma once

#include <vector>

#include "core/integrators/ode.h"
#include "core/model/model.h"
#include "core/model/motion.h"
#include "core/run/result.h"

namespace vibro {

// Counts of impacts by kind, limiter and pellet, and the last impact, from the events sorted by
// time; the final states are left to final_states().
Summary summarize(const Model& model, const std::vector<Event>& sorted_events);

// Whether impacts have stopped by the end of the run (t_reached): none happened, everything
// rests for good, or the spell since the last impact is longer than three times the longest
// spell between impacts before it (the first counted from t = 0). A run stopped early cannot say
// that its impacts stopped.
bool ends_vibro_impact(const std::vector<Event>& sorted_events, double t_reached, bool completed,
                       bool at_rest_for_good);

// Per pellet: where it is at the end (state y) and how it moves (its body's mode).
std::vector<FinalState> final_states(const Model& model, const std::vector<Body>& bodies,
                                     const Vec& y);

}  // namespace vibro
