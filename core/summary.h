// The summary of a run (MODEL.md, "What a run must answer"), built in one pass over its events.
#pragma once

#include <vector>

#include "core/model.h"
#include "core/motion.h"
#include "core/ode.h"
#include "core/result.h"

namespace vibro {

// Counts of impacts by kind, limiter and pellet, and the last impact, from the events sorted by
// time; the final states are left to final_states().
Summary summarize(const Model& model, const std::vector<Event>& sorted_events);

// Per pellet: where it is at the end (state y) and how it moves (its body's mode).
std::vector<FinalState> final_states(const Model& model, const std::vector<Body>& bodies,
                                     const Vec& y);

}  // namespace vibro
