// What of a run falls inside a panel's time window [t_from, t_to], or at one instant.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/run/result.h"
#include "render/plot_spec.h"

namespace vibro::render {

// The samples of a branch inside [t_from, t_to], with points interpolated linearly at the
// window's edges where the branch crosses them; empty when the branch lies outside.
std::vector<Sample> clip_to_window(std::span<const Sample> samples, double t_from, double t_to);

// The recorded track of `pellet`, or null when the run did not record it.
const PelletTrack* find_track(const RunResult& run, int pellet);

// The pellet's state at time t, interpolated linearly between the samples around it. Where no
// branch spans t (a pellet at rest that the run stopped sampling, or t past the record) it holds
// the last sample before t; before the first sample, the first. Nothing for a track without
// samples.
std::optional<Sample> state_at(const PelletTrack& track, double t);

// The pellets of the run a panel draws: `pellet` for phase and cylinder panels; `pellets` for
// time panels, or every pellet of the model when that list is empty; every pellet for mechanism
// panels; none for the kinds that draw a sweep, a report or a branch.
std::vector<int> panel_pellets(const PlotSpec& spec, int pellet_count);

// The marked event (limiter impact, collision, chatter) touching `pellet` at time t (within
// round-off), or null. `events` are in time order.
const Event* find_impact(std::span<const Event> events, int pellet, double t);

// Whether the event touches the pellet.
bool touches(const Event& event, int pellet);

// Whether a phase panel draws branch number `index` (all when `branches` is empty).
bool branch_selected(const PhasePlot& spec, int index);

// ", t ∈ [2, 6] s" for a title when the window restricts the run, else empty. Times after
// `t_end` (the end of the run) count as unrestricted.
std::string window_suffix(const TimeWindow& spec, double t_end);

// Whether event time t is inside the window.
inline bool in_window(double t, const TimeWindow& spec) {
  return t >= spec.t_from && t <= spec.t_to;
}

}  // namespace vibro::render
